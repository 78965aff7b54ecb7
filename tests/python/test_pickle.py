"""Instances, fragment sets and pose graphs pickle bit for bit (so that multiprocessing can carry
them), and a state this antslam did not write is one clear error."""
import concurrent.futures
import multiprocessing
import pickle

import numpy as np
import pytest

import antslam
from conftest import DATA, GRAPHS, SOURCE

FIXTURES = SOURCE / "tests" / "tsp" / "fixtures"


def round_trip(value):
    return pickle.loads(pickle.dumps(value))


@pytest.mark.parametrize("path", [DATA / "tsplib" / "eil51.tsp", FIXTURES / "gr17.tsp",
                                  FIXTURES / "burma14.tsp"])
def test_an_instance_pickles_with_every_distance(path):
    instance = antslam.tsp.read(path)
    copy = round_trip(instance)
    assert (copy.name, copy.comment, copy.edge_weight_type, len(copy)) == (
        instance.name, instance.comment, instance.edge_weight_type, len(instance))
    np.testing.assert_array_equal(copy.coords, instance.coords)
    n = len(instance)
    assert all(copy.distance(i, j) == instance.distance(i, j) for i in range(n) for j in range(n))
    a = antslam.tsp.solve(instance, iterations=20, seed=5)
    b = antslam.tsp.solve(copy, iterations=20, seed=5)
    np.testing.assert_array_equal(a.tour, b.tour)


def test_a_generated_instance_keeps_every_bit_of_its_coordinates():
    instance = antslam.tsp.generate(200, seed=9, side=1.0)  # coordinates in [0, 1): many digits
    np.testing.assert_array_equal(round_trip(instance).coords, instance.coords)


def test_a_fragment_set_pickles_with_its_samples_and_gives_the_same_optimum():
    fragment_set = antslam.slam.load(DATA / "fragment-sets" / "paper9.json")
    copy = round_trip(fragment_set)
    assert copy.name == fragment_set.name and copy.closures == fragment_set.closures
    np.testing.assert_array_equal(copy.means, fragment_set.means)
    np.testing.assert_array_equal(copy.reference, fragment_set.reference)
    for k in range(len(fragment_set)):
        np.testing.assert_array_equal(copy.samples(k), fragment_set.samples(k))
    a = antslam.slam.optimize(fragment_set, "mmas", iterations=20, seed=4)
    b = antslam.slam.optimize(copy, "mmas", iterations=20, seed=4)
    assert a.weight == b.weight


@pytest.mark.parametrize("name", ["edges-only.g2o", "two-sessions.g2o"])
def test_a_pose_graph_pickles_with_its_name_fixed_vertices_and_origin(name):
    graph = antslam.slam.read_graph(GRAPHS / name)
    graph.fixed = [1]
    graph.vertices = graph.vertices + 1e-7 / 3  # digits no short decimal holds
    copy = round_trip(graph)
    assert (copy.name, copy.fixed, copy.vertices_from_file, len(copy)) == (
        graph.name, [1], graph.vertices_from_file, len(graph))
    for field in ("vertices", "edges", "measurements", "information"):
        np.testing.assert_array_equal(getattr(copy, field), getattr(graph, field))


def tour_length_elsewhere(instance, tour):
    return instance.tour_length(tour)


def test_multiprocessing_carries_an_instance_to_another_process():
    instance = antslam.tsp.read(DATA / "tsplib" / "eil51.tsp")
    tour = instance.read_tour(DATA / "tsplib" / "eil51.opt.tour")
    context = multiprocessing.get_context("fork")
    with concurrent.futures.ProcessPoolExecutor(1, mp_context=context) as pool:
        assert pool.submit(tour_length_elsewhere, instance, tour).result() == 426.0


def test_a_state_this_antslam_did_not_write_is_one_clear_error():
    instance = antslam.tsp.read(FIXTURES / "burma14.tsp")
    state = instance.__getstate__()
    with pytest.raises(ValueError, match=r"^antslam.tsp.Instance: not a pickle this antslam "
                                         r"reads \(format version 1\)$"):
        antslam.tsp.Instance.__new__(antslam.tsp.Instance).__setstate__((2, state[1]))
    truncated = (state[0], state[1][: len(state[1]) // 2])
    with pytest.raises(RuntimeError, match=r"^pickled antslam.tsp.Instance"):
        antslam.tsp.Instance.__new__(antslam.tsp.Instance).__setstate__(truncated)
    graph = antslam.slam.read_graph(GRAPHS / "two-sessions.g2o")
    with pytest.raises(ValueError, match=r"^antslam.slam.PoseGraph: not a pickle"):
        antslam.slam.PoseGraph.__new__(antslam.slam.PoseGraph).__setstate__(
            graph.__getstate__()[:2])
