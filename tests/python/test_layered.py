"""antslam.aco: a layered-choice problem from numpy tables and a Python term, solved by every
variant; checked against brute force, across backends, and for bad input."""
import numpy as np
import pytest

import antslam


def small_problem(seed=3):
    """4 layers of 3-5 options, pairwise tables between neighbours, a term of the whole choice
    that makes the problem non-separable."""
    rng = np.random.default_rng(seed)
    costs = [rng.random(k) for k in (3, 5, 4, 3)]
    pairwise = [rng.random((len(a), len(b))) for a, b in zip(costs, costs[1:])]

    def term(choice):
        assert choice.dtype == np.uint32 and len(choice) == 4
        return float((int(choice.sum()) % 4) * 0.3)
    return costs, pairwise, term


def cost_of(costs, pairwise, term, choice):
    total = sum(costs[l][c] for l, c in enumerate(choice))
    total += sum(pairwise[l][choice[l], choice[l + 1]] for l in range(len(pairwise)))
    return total + term(choice)


def test_brute_force_is_the_minimum_by_hand():
    costs = np.array([[1.0, 0.0], [0.0, 2.0]])
    pairwise = [np.array([[0.0, 0.0], [5.0, 0.0]])]
    # (0, 0): 1 + 0 + 0 = 1; (1, 0): 0 + 0 + 5 = 5; (0, 1): 1 + 2 = 3; (1, 1): 0 + 2 + 0 = 2.
    assert antslam.aco.brute_force(costs, pairwise)[0] == 1.0
    assert list(antslam.aco.brute_force(costs, pairwise)[1]) == [0, 0]


@pytest.mark.parametrize("variant", antslam.aco.VARIANTS)
def test_every_variant_finds_the_brute_force_optimum(variant):
    # One run may stagnate early (ACS with its q0 = 0.9 does in 3 of these 5 seeds), so the
    # claim is about the best of five seeds; no run may report a cost it did not reach.
    costs, pairwise, term = small_problem()
    optimum, best = antslam.aco.brute_force(costs, pairwise, term)
    runs = [antslam.aco.solve(costs, pairwise, term, variant=variant, iterations=150, seed=seed)
            for seed in range(1, 6)]
    for r in runs:
        assert r.cost == cost_of(costs, pairwise, term, r.choice)  # the engine's cost, recomputed
        assert r.cost >= optimum - 1e-12
        assert r.variant == variant
    assert min(r.cost for r in runs) == pytest.approx(optimum, abs=1e-12)


@pytest.mark.parametrize("variant", antslam.aco.VARIANTS)
def test_the_same_choice_on_every_backend_and_thread_count(variant):
    rng = np.random.default_rng(9)
    costs = rng.random((12, 6))
    pairwise = rng.random((11, 6, 6))
    term = lambda c: float(np.sin(c.astype(float)).sum() + 12)  # noqa: E731
    runs = [antslam.aco.solve(costs, pairwise, term, variant=variant, iterations=20, seed=4,
                              backend=backend, threads=threads)
            for backend, threads in (("serial", 1), ("omp", 2), ("tbb", 2), ("auto", 2))]
    for run in runs[1:]:
        assert run.cost == runs[0].cost
        assert np.array_equal(run.choice, runs[0].choice)


def test_a_two_dimensional_table_layers_of_different_sizes_and_a_heuristic():
    costs = [np.array([3.0, 1.0]), np.array([2.0, 2.0, 0.5])]
    r = antslam.aco.solve(costs, heuristic=[np.ones(2), np.array([1.0, 1.0, 5.0])],
                          iterations=30, seed=1)
    assert list(r.choice) == [1, 2] and r.cost == 1.5
    r = antslam.aco.solve(np.array([[2.0, 1.0, 3.0]] * 3), variant="as", iterations=30)
    assert list(r.choice) == [1, 1, 1] and r.cost == 3.0


def test_bad_tables_and_terms_are_refused():
    with pytest.raises(ValueError, match=r"^costs\[1\]\[0\] = -1\.0+ is not a finite number >= 0$"):
        antslam.aco.solve([np.ones(2), np.array([-1.0])])
    with pytest.raises(ValueError, match=r"^costs\[0\]\[1\] = -?nan is not a finite number >= 0$"):
        antslam.aco.solve(np.array([[1.0, np.nan]]))
    with pytest.raises(ValueError, match=r"^pairwise\[0\]: expected shape \(2, 3\), got \(3, 2\)$"):
        antslam.aco.solve([np.ones(2), np.ones(3)], [np.ones((3, 2))])
    with pytest.raises(ValueError, match=r"^pairwise: 2 tables for 2 layers"):
        antslam.aco.solve([np.ones(2), np.ones(2)], [np.ones((2, 2))] * 2)
    with pytest.raises(ValueError, match=r"^costs\[0\]: a layer without options$"):
        antslam.aco.solve([np.ones(0)])
    with pytest.raises(ValueError, match=r"^term: returned -1\.0, expected a finite number >= 0$"):
        antslam.aco.solve(np.ones((3, 3)), term=lambda c: -1.0)
    with pytest.raises(ZeroDivisionError):
        antslam.aco.solve(np.ones((3, 3)), term=lambda c: 1 / 0, iterations=10**6, threads=2)
    with pytest.raises(ValueError, match=r"^backend: unknown 'gpu' \(expected one of auto, "):
        antslam.aco.solve(np.ones((2, 2)), backend="gpu")
    with pytest.raises(ValueError, match=r"^aco: p0 must be in \[0, 1\]$"):
        antslam.aco.solve(np.ones((2, 2)), variant="hybrid", p0=2)
