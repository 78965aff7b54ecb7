"""antslam.clique: the ants, branch and bound and the greedy baseline against brute force on
small weighted graphs, the seed's result on any thread count and backend, and bad input."""
import itertools

import numpy as np
import pytest

import antslam


def random_graph(n, p, seed, weighted):
    rng = np.random.default_rng(seed)
    edges = [(i, j) for i, j in itertools.combinations(range(n), 2) if rng.random() < p]
    weights = rng.integers(1, 4, n).tolist() if weighted else None
    return antslam.clique.Graph(n, edges, weights), edges, weights


def brute_force(n, edges, weights):
    """The maximum clique weight over all 2^n vertex subsets."""
    adjacent = set(edges) | {(j, i) for i, j in edges}
    w = weights or [1] * n
    best = 0
    for mask in range(1, 1 << n):
        members = [v for v in range(n) if mask >> v & 1]
        if all((a, b) in adjacent for a, b in itertools.combinations(members, 2)):
            best = max(best, sum(w[v] for v in members))
    return best


def test_the_module_example():
    g = antslam.clique.Graph(5, [(0, 1), (0, 2), (1, 2), (2, 3), (3, 4)])
    found = antslam.clique.aco(g, seed=2)
    best = antslam.clique.exact(g)
    assert found.weight == 3.0 and best.optimal
    assert repr(best) == "<antslam.clique.Clique of 3 vertices: weight 3, upper bound 3, proven maximum>"
    np.testing.assert_array_equal(found.vertices, [0, 1, 2])
    assert found.stop_reason == "target"  # the colouring bound 3 is reached: proven


@pytest.mark.parametrize("weighted", [False, True])
@pytest.mark.parametrize("seed", range(1, 9))
def test_every_search_against_brute_force(seed, weighted):
    g, edges, weights = random_graph(12, 0.5, seed, weighted)
    best = brute_force(12, edges, weights)
    exact = antslam.clique.exact(g)
    assert exact.optimal and exact.weight == best and g.is_clique(exact.vertices)
    for options in ({}, {"plateau_steps": 10}, {"restart_stagnant": 3}):
        ants = antslam.clique.aco(g, seed=seed, **options)
        assert ants.weight == best and g.is_clique(ants.vertices)
        assert g.weight_of(ants.vertices) == ants.weight
    greedy = antslam.clique.greedy(g)
    assert g.is_clique(greedy.vertices) and greedy.weight <= best
    weak = dict(ants=1, iterations=1, local_search=False)  # one ant's clique, as built
    proved = antslam.clique.aco(g, seed=seed, proof_nodes=10**6, **weak)
    assert proved.weight == best and proved.clique.optimal and g.is_clique(proved.vertices)
    assert antslam.clique.aco(g, seed=seed, proof_nodes=0, **weak).weight <= best


def test_the_seed_gives_the_same_clique_on_every_thread_count_and_backend():
    g, _, _ = random_graph(120, 0.6, 3, True)
    one = antslam.clique.aco(g, seed=5, stagnation=0, iterations=15, backend="serial")
    for backend, threads in (("tbb", 2), ("omp", 2), ("tbb", 1)):
        other = antslam.clique.aco(g, seed=5, stagnation=0, iterations=15, backend=backend,
                                   threads=threads)
        np.testing.assert_array_equal(other.vertices, one.vertices)
        assert other.iterations == one.iterations == 15


def test_the_defaults_are_the_programs():
    s = antslam.clique.AcoSettings()
    assert (s.parameters.variant, s.termination.max_iterations,
            s.termination.stagnation_iterations, s.plateau_steps,
            s.parameters.restart_stagnant) == ("mmas", 100, 20, 0, 0)


@pytest.mark.parametrize("vertices, edges, weights, message", [
    (3, [(0, 1, 2)], None, r"edges: expected an \(m, 2\) array"),
    (3, [(0, 3)], None, r"clique graph: edge .*3"),
    (3, [(1, 1)], None, r"clique graph: edge"),
    (3, [(0, -1)], None, r"edges: entry 1 \(-1\) is not an index"),
    (3, [(0.5, 1)], None, r"edges: expected integers"),
    (3, [(0, 1)], [1, 1], r"clique graph: 2 weights"),
    (3, [(0, 1)], [1, float("nan"), 1], r"clique graph: weight of vertex 1"),
    (3, [(0, 1)], [1, 0, 1], r"clique graph: weight of vertex 1"),
])
def test_bad_graphs_are_one_line_errors(vertices, edges, weights, message):
    with pytest.raises(ValueError, match=message):
        antslam.clique.Graph(vertices, edges, weights)


@pytest.mark.parametrize("vertices", [-1, 3.5, "3", True])
def test_a_bad_vertex_count_is_one_line(vertices):
    with pytest.raises(ValueError, match=r"vertices: expected a count >= 0, got"):
        antslam.clique.Graph(vertices, [])


def test_a_graph_too_large_is_one_line():
    # 2^31 vertices: 2^59 bytes (576,460,752,303.4 MB) of adjacency bits, beyond any address space.
    with pytest.raises(ValueError, match=r"clique graph: the adjacency bits of 2147483648 "
                                         r"vertices \(576460752303 MB\) do not fit in memory"):
        antslam.clique.Graph(2**31, [])
    with pytest.raises(ValueError, match=r"clique graph: 1099511627776 vertices \(at most "
                                         r"4294967295\)"):
        antslam.clique.Graph(2**40, [])


def test_bad_options_are_one_line_errors():
    g = antslam.clique.Graph(3, [(0, 1)])
    with pytest.raises(TypeError, match="unexpected keyword argument 'plateau'"):
        antslam.clique.aco(g, plateau=3)
    with pytest.raises(ValueError, match="backend: unknown 'gpu'"):
        antslam.clique.aco(g, backend="gpu")
    with pytest.raises(ValueError, match="variant: unknown 'bees'"):
        antslam.clique.aco(g, variant="bees")
    with pytest.raises(ValueError, match="set iterations, a time budget or stagnation"):
        antslam.clique.aco(g, iterations=0, stagnation=0)
    with pytest.raises(ValueError, match="termination: the time limit must be a finite number"):
        antslam.clique.aco(g, time_limit=float("nan"))
    with pytest.raises(ValueError, match="exact clique search: time limit must be a finite"):
        antslam.clique.exact(g, time_limit=-1)
    with pytest.raises(ValueError, match="the graph is empty"):
        antslam.clique.aco(antslam.clique.Graph(0, []))
