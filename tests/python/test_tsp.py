"""antslam.tsp: instances, the solver with every variant and backend, the program's tour for the
same seed, the observer, and one-line errors."""
import pickle

import numpy as np
import pytest

import antslam
from conftest import DATA, SOURCE

FIXTURES = SOURCE / "tests" / "tsp" / "fixtures"


def test_read_gives_the_instance_and_its_tsplib_distances():
    instance = antslam.tsp.read(DATA / "tsplib" / "eil51.tsp")
    assert (instance.name, len(instance), instance.edge_weight_type) == ("eil51", 51, "EUC_2D")
    assert instance.coords.shape == (51, 2)
    # EUC_2D: the Euclidean distance rounded to the nearest integer (TSPLIB 95).
    a, b = instance.coords[0], instance.coords[1]
    assert instance.distance(0, 1) == np.floor(np.hypot(*(a - b)) + 0.5)
    tour = instance.read_tour(DATA / "tsplib" / "eil51.opt.tour")
    assert instance.tour_length(tour) == 426.0


def test_solve_returns_a_tour_and_its_length():
    instance = antslam.tsp.read(FIXTURES / "ulysses16.tsp")
    result = antslam.tsp.solve(instance, variant="mmas", iterations=30, seed=3)
    assert sorted(result.tour) == list(range(16))
    assert result.tour.dtype == np.uint32
    assert result.length == instance.tour_length(result.tour)
    assert result.length == 6859.0  # the optimum (ulysses16.opt.tour)
    assert (result.iterations, result.stop_reason, result.threads) == (30, "iterations", 1)


@pytest.mark.parametrize("variant", antslam.aco.VARIANTS)
def test_every_variant_gives_the_same_tour_on_every_backend(variant):
    instance = antslam.tsp.read(DATA / "tsplib" / "eil51.tsp")
    runs = [antslam.tsp.solve(instance, variant=variant, iterations=15, seed=5,
                              local_search="2opt", backend=backend, threads=threads)
            for backend, threads in (("serial", 1), ("omp", 2), ("tbb", 2))]
    for run in runs[1:]:
        assert run.length == runs[0].length
        assert np.array_equal(run.tour, runs[0].tour)
    assert runs[0].variant == variant
    assert runs[1].backend == "omp" and runs[2].threads == 2


def test_same_seed_same_tour_as_the_program(program, tmp_path):
    path = DATA / "tsplib" / "berlin52.tsp"
    out = program("tsp", "--instance", path, "--variant", "acs", "--iterations", 40, "--seed", 7,
                  "--local-search", "2.5opt", "--ants", 12, "--q0", 0.8,
                  "--tour-out", tmp_path / "b.tour")
    instance = antslam.tsp.read(path)
    result = antslam.tsp.solve(instance, variant="acs", iterations=40, seed=7,
                               local_search="2.5opt", ants=12, q0=0.8)
    assert np.array_equal(instance.read_tour(tmp_path / "b.tour"), result.tour)
    assert f"best length  {result.length:g}" in out


def test_focused_construction_as_the_program(program, tmp_path):
    path = DATA / "tsplib" / "pcb442.tsp"
    program("tsp", "--instance", path, "--variant", "mmas", "--iterations", 5, "--seed", 2,
            "--focused-edges", 4, "--tour-out", tmp_path / "f.tour")
    instance = antslam.tsp.read(path)
    focused = antslam.tsp.solve(instance, iterations=5, seed=2, focused_edges=4)
    assert np.array_equal(instance.read_tour(tmp_path / "f.tour"), focused.tour)
    # MAX-MIN's default is focused construction with 8 new edges; 0 builds from nothing.
    default = antslam.tsp.solve(instance, iterations=5, seed=2)
    assert np.array_equal(default.tour, antslam.tsp.solve(instance, iterations=5, seed=2,
                                                          focused_edges=8).tour)
    plain = antslam.tsp.solve(instance, iterations=5, seed=2, focused_edges=0)
    assert not np.array_equal(plain.tour, default.tour)  # the option reaches the engine
    assert not np.array_equal(focused.tour, default.tour)


def test_islands_as_the_program(program, tmp_path):
    path = DATA / "tsplib" / "pcb442.tsp"
    program("tsp", "--instance", path, "--iterations", 20, "--seed", 4, "--colonies", 3,
            "--exchange-every", 4, "--topology", "full", "--tour-out", tmp_path / "k3.tour")
    instance = antslam.tsp.read(path)
    islands = antslam.tsp.solve(instance, iterations=20, seed=4, colonies=3, exchange_every=4,
                                topology="full")
    assert np.array_equal(instance.read_tour(tmp_path / "k3.tour"), islands.tour)
    plain = antslam.tsp.solve(instance, iterations=20, seed=4)
    assert not np.array_equal(plain.tour, islands.tour)  # the colonies reach the engine
    with pytest.raises(ValueError, match="topology"):
        antslam.tsp.solve(instance, iterations=2, colonies=2, topology="star")


def test_the_observer_hears_every_iteration():
    instance = antslam.tsp.read(FIXTURES / "burma14.tsp")
    reports = []
    result = antslam.tsp.solve(instance, iterations=12, seed=1, local_search="none",
                               observer=reports.append)
    assert [r.iteration for r in reports] == list(range(1, 13))
    bests = [r.global_best for r in reports]
    assert bests == sorted(bests, reverse=True)
    assert bests[-1] == result.length
    assert np.array_equal(reports[-1].best, result.tour)


def test_stop_criteria():
    instance = antslam.tsp.read(FIXTURES / "ulysses16.tsp")
    r = antslam.tsp.solve(instance, iterations=1000, seed=3, target=6859)
    assert r.stop_reason == "target" and r.length == 6859 and r.iterations < 1000
    r = antslam.tsp.solve(instance, iterations=0, seed=3, stagnation=5)
    assert r.stop_reason == "stagnation" and r.iterations - r.best_iteration == 5


def test_errors_are_one_line():
    instance = antslam.tsp.read(FIXTURES / "burma14.tsp")
    with pytest.raises(ValueError, match=r"^variant: unknown 'mmmas' \(expected one of as, "):
        antslam.tsp.solve(instance, variant="mmmas")
    with pytest.raises(ValueError, match=r"^aco: rho must be in \[0, 1\]"):
        antslam.tsp.solve(instance, rho=1.5)
    with pytest.raises(ValueError, match=r"^local_search: unknown '4opt'"):
        antslam.tsp.solve(instance, local_search="4opt")
    with pytest.raises(ValueError, match=r"^backend serial runs on exactly 1 thread, not 2$"):
        antslam.tsp.solve(instance, backend="serial", threads=2)
    with pytest.raises(ValueError, match=r"^termination: set iterations"):
        antslam.tsp.solve(instance, iterations=0)
    with pytest.raises(TypeError, match=r"^solve\(\) got an unexpected keyword argument 'rhoo'$"):
        antslam.tsp.solve(instance, rhoo=0.1)
    with pytest.raises(ValueError, match=r"^solve\(\): ants=-1 must be a whole number >= 0$"):
        antslam.tsp.solve(instance, ants=-1)
    with pytest.raises(TypeError, match=r"^solve\(\): ants='many' has the wrong type$"):
        antslam.tsp.solve(instance, ants="many")
    with pytest.raises(ValueError, match=r"^tour: expected a permutation of 0..13$"):
        instance.tour_length([0] * 14)
    with pytest.raises(RuntimeError, match=r"nan_coordinate\.tsp:\d+: "):
        antslam.tsp.read(FIXTURES / "nan_coordinate.tsp")
    with pytest.raises(RuntimeError, match=r"missing\.tsp"):
        antslam.tsp.read(FIXTURES / "missing.tsp")


def test_a_binary_file_is_one_line_naming_it(tmp_path):
    binary = tmp_path / "binary.tsp"
    binary.write_bytes(b"NAME: \xff\xfe\x00\x81\nTYPE: TSP\n\x89PNG\r\n")
    with pytest.raises(RuntimeError) as error:
        antslam.tsp.read(binary)
    message = str(error.value)
    assert message.startswith(str(binary)) and "\\x" in message and "\n" not in message


def test_generate_and_save_round_trip(tmp_path):
    instance = antslam.tsp.generate(40, seed=4, side=1000)
    instance.save(tmp_path / "r.tsp")
    again = antslam.tsp.read(tmp_path / "r.tsp")
    assert np.array_equal(again.coords, instance.coords)


def test_an_instance_from_coordinates_is_the_tsplib_file_of_them(tmp_path):
    read = antslam.tsp.read(DATA / "tsplib" / "eil51.tsp")
    built = antslam.tsp.Instance(read.coords, name="eil51")
    assert (built.name, len(built), built.edge_weight_type) == ("eil51", 51, "EUC_2D")
    n = len(read)
    assert all(built.distance(i, j) == read.distance(i, j) for i in range(n) for j in range(n))
    # The same instance, so the same tour for the same seed.
    a = antslam.tsp.solve(read, iterations=20, seed=5)
    b = antslam.tsp.solve(built, iterations=20, seed=5)
    assert list(a.tour) == list(b.tour) and a.length == b.length
    ceil = antslam.tsp.Instance([[0, 0], [0.5, 0], [3, 4]], edge_weight_type="CEIL_2D")
    assert (ceil.distance(0, 1), ceil.distance(0, 2)) == (1.0, 5.0)
    built.save(tmp_path / "built.tsp")
    assert np.array_equal(antslam.tsp.read(tmp_path / "built.tsp").coords, read.coords)


def test_an_instance_from_a_distance_matrix():
    matrix = np.array([[0, 3, 4, 5], [3, 0, 5, 4], [4, 5, 0, 3], [5, 4, 3, 0]])
    instance = antslam.tsp.Instance.from_matrix(matrix, name="square")
    assert (instance.name, len(instance), instance.edge_weight_type) == ("square", 4, "EXPLICIT")
    assert all(instance.distance(i, j) == matrix[i, j] for i in range(4) for j in range(4))
    # The 3 tours of 4 cities: 0-1-2-3 3+5+3+5 = 16, 0-2-1-3 4+5+4+5 = 18, 0-1-3-2 3+4+3+4 = 14.
    lengths = [instance.tour_length(t) for t in ([0, 1, 2, 3], [0, 2, 1, 3], [0, 1, 3, 2])]
    assert lengths == [16.0, 18.0, 14.0]
    assert antslam.tsp.solve(instance, iterations=10, seed=1).length == 14.0
    again = pickle.loads(pickle.dumps(instance))
    assert all(again.distance(i, j) == matrix[i, j] for i in range(4) for j in range(4))


def test_built_instances_refuse_bad_arrays_in_one_line():
    with pytest.raises(ValueError, match=r"^Instance: coords: expected an \(n, 2\) array"):
        antslam.tsp.Instance(np.zeros((5, 3)))
    with pytest.raises(ValueError, match=r"^Instance: edge_weight_type 'MAN_2D' is not one of"):
        antslam.tsp.Instance(np.zeros((5, 2)), edge_weight_type="MAN_2D")
    with pytest.raises(ValueError, match=r"finite"):
        antslam.tsp.Instance([[0, 0], [1, np.nan], [2, 2]])
    with pytest.raises(ValueError, match=r"^Instance.from_matrix: expected an \(n, n\) array"):
        antslam.tsp.Instance.from_matrix(np.zeros((3, 4)))
    with pytest.raises(ValueError, match=r"^Instance.from_matrix: entry \(0, 1\) is 1.5, not a whole"):
        antslam.tsp.Instance.from_matrix([[0, 1.5, 2], [1.5, 0, 2], [2, 2, 0]])
    with pytest.raises(ValueError, match=r"^Instance.from_matrix: entry \(0, 2\) is -2, not a whole"):
        antslam.tsp.Instance.from_matrix([[0, 1, -2], [1, 0, 2], [-2, 2, 0]])
    with pytest.raises(ValueError, match=r"symmetric"):
        antslam.tsp.Instance.from_matrix([[0, 1, 2], [1, 0, 2], [3, 2, 0]])
