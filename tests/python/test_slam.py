"""antslam.slam on fragment sets: synthesize, load, save, from g2o; every method with its result
consistent with the model; the program's result for the same seed; trials on any thread count."""
import json

import numpy as np
import pytest

import antslam
from conftest import DATA

PAPER9 = DATA / "fragment-sets" / "paper9.json"


@pytest.fixture(scope="module")
def small():
    """A set small enough for exhaustive search: 5 fragments of 4 samples, 2 laps."""
    return antslam.slam.synth(fragments=5, samples=4, seed=3)


def test_synth_load_save_round_trip(tmp_path):
    s = antslam.slam.synth("paper15", seed=1)
    assert (len(s), s.layer_count, s.closures) == (15, 14, [(0, 14)])
    assert s.reference.shape == (15, 3) and s.means.shape == (14, 3)
    assert s.samples(3).shape == (20, 3)
    s.save(tmp_path / "s.json")
    again = antslam.slam.load(tmp_path / "s.json")
    assert np.array_equal(again.means, s.means)
    assert np.array_equal(again.samples(7), s.samples(7))
    # The shipped paper set is this preset with seed 1 (data/fragment-sets/README.md).
    assert np.array_equal(antslam.slam.load(DATA / "fragment-sets" / "paper15.json").means, s.means)


@pytest.mark.parametrize("method", antslam.slam.METHODS)
def test_every_method_returns_a_result_consistent_with_the_set(small, method):
    r = antslam.slam.optimize(small, method=method, iterations=40, seed=2)
    assert r.method == method
    assert r.alignments.shape == (4, 3) and r.frames.shape == (5, 3)
    np.testing.assert_allclose(r.frames, antslam.slam.chain(r.alignments), atol=1e-12)
    assert (r.weight, r.chi2) == small.score(r.alignments)
    optimum = antslam.slam.optimize(small, method="exhaustive").weight
    if method == "hybrid+nlopt":  # the ants' choice is the start of the refinement
        assert r.weight <= small.path_weight(r.choice) + 1e-12
    elif len(r.choice):
        assert r.weight == pytest.approx(small.path_weight(r.choice), abs=1e-12)
        assert r.weight >= optimum - 1e-12
    assert r.convergence.shape[1] == 4 and r.convergence[-1, 3] >= r.weight - 1e-12


def test_same_seed_same_result_as_the_program(program, tmp_path):
    program("optimize", PAPER9, "--method", "hybrid+nlopt", "--iterations", 200, "--seed", 4,
            "--rho", 0.5, "--max-evaluations", 300, "-o", tmp_path / "p")
    expected = json.loads((tmp_path / "p.json").read_text())["best"]
    s = antslam.slam.load(PAPER9)
    r = antslam.slam.optimize(s, method="hybrid+nlopt", iterations=200, seed=4, rho=0.5,
                              max_evaluations=300)
    assert r.weight == expected["weight"] and r.chi2 == expected["chi2"]
    assert list(r.choice) == expected["choice"]
    np.testing.assert_array_equal(r.frames, np.array(expected["frames"]))


def test_a_study_does_not_depend_on_threads_and_matches_the_program(program, tmp_path):
    s = antslam.slam.load(PAPER9)
    one = antslam.slam.study(s, method="mmas", trials=4, threads=1, iterations=100, seed=9)
    two = antslam.slam.study(s, method="mmas", trials=4, threads=2, iterations=100, seed=9)
    assert [r.weight for r in one.results] == [r.weight for r in two.results]
    assert one.best.weight == min(r.weight for r in one.results) == one.weight.min
    program("optimize", PAPER9, "--method", "mmas", "--trials", 4, "--iterations", 100,
            "--seed", 9, "-o", tmp_path / "m")
    rows = (tmp_path / "m.trials.csv").read_text().splitlines()[1:]
    assert [float(row.split(",")[2]) for row in rows] == [r.weight for r in one.results]


def test_observer_initial_and_progress(small):
    points = []
    r = antslam.slam.optimize(small, method="acs", iterations=60, seed=1, observer=points.append)
    assert [p.best_weight for p in points] == list(r.convergence[:, 3])
    means = small.means
    a = antslam.slam.optimize(small, method="nlopt")
    b = antslam.slam.optimize(small, method="nlopt", initial=means)
    assert a.weight == b.weight
    finished = []
    antslam.slam.study(small, method="random", trials=3, iterations=5, progress=finished.append)
    assert sorted(finished) == [1, 2, 3]


def test_errors_are_one_line(small, tmp_path):
    with pytest.raises(ValueError, match=r"^unknown method 'hybird' \(expected one of as, "):
        antslam.slam.optimize(small, method="hybird")
    with pytest.raises(ValueError, match=r"^optimize: aco: rho must be in \[0, 1\]"):
        antslam.slam.optimize(small, rho=3)
    with pytest.raises(ValueError, match=r"^optimize: initial has 2 alignments, expected 4$"):
        antslam.slam.optimize(small, method="nlopt", initial=np.zeros((2, 3)))
    with pytest.raises(ValueError, match=r"^unknown NLopt algorithm 'newton'"):
        antslam.slam.optimize(small, method="nlopt", nlopt_algorithm="newton")
    with pytest.raises(ValueError, match=r"^exhaustive search over \d+ paths exceeds the limit of 10$"):
        antslam.slam.optimize(small, method="exhaustive", max_paths=10)
    with pytest.raises(TypeError, match=r"^optimize\(\): expected a FragmentSet or a PoseGraph"):
        antslam.slam.optimize("set.json")
    (tmp_path / "bad.json").write_text('{"format": "antslam-fragment-set", "version": 1}')
    with pytest.raises(RuntimeError, match=r"bad\.json: "):
        antslam.slam.load(tmp_path / "bad.json")
