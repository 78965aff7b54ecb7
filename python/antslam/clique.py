"""Maximum (weighted) cliques: the searches that choose which loop closures `antslam robust
--method pcm-aco / pcm-exact` trusts, on any graph.

    g = antslam.clique.Graph(5, [(0, 1), (0, 2), (1, 2), (2, 3), (3, 4)])
    found = antslam.clique.aco(g, seed=2)        # the ants: MAX-MIN with (1,2)-swaps
    best = antslam.clique.exact(g)               # branch and bound, proven maximum
    found.weight, found.vertices, best.optimal   # 3.0, array([0, 1, 2]), True
"""
from dataclasses import dataclass

import numpy as np

from . import _core, _options

Clique = _core.clique.Clique
AcoSettings = _core.clique.AcoSettings


class Graph(_core.clique.Graph):
    """An undirected graph on the vertices 0..vertices-1: edges an (m, 2) array or a sequence of
    pairs, weights positive (default: 1 each, the maximum clique by cardinality)."""

    def __init__(self, vertices, edges, weights=None):
        if isinstance(vertices, bool) or not isinstance(vertices, (int, np.integer)) \
                or vertices < 0:
            raise ValueError(f"vertices: expected a count >= 0, got {vertices!r}")
        pairs = np.asarray(edges)
        if pairs.size == 0:
            pairs = np.zeros((0, 2), dtype=np.int64)
        if pairs.ndim != 2 or pairs.shape[1] != 2:
            raise ValueError(f"edges: expected an (m, 2) array of vertex pairs, got shape "
                             f"{pairs.shape}")
        super().__init__(vertices, pairs.reshape(-1),
                         [] if weights is None else [float(w) for w in weights])


@dataclass(frozen=True)
class AcoResult:
    """The ants' clique and what ran."""
    clique: Clique
    iterations: int
    stop_reason: str  #: iterations, time, target (the colouring bound: proven), stagnation, ...

    @property
    def weight(self):
        return self.clique.weight

    @property
    def vertices(self):
        return self.clique.vertices


_SEARCH = {"local_search": "local_search", "plateau_steps": "plateau_steps",
           "proof_nodes": "proof_nodes", "backend": "backend", "threads": "threads"}
_STOP = {"iterations": "max_iterations", "stagnation": "stagnation_iterations",
         "time_limit": "time_limit_s"}


def aco(graph, variant=None, seed=1, **options):
    """The ants' maximum clique, as `antslam robust --method pcm-aco` searches it. Options (the
    defaults are the program's): iterations, stagnation (iterations without a better clique),
    time_limit (s), local_search (False: the ants' cliques as built), plateau_steps (plateau
    moves after each ant's (1,2)-swaps; 0, the default: none; docs/robust-closures.md),
    proof_nodes (then branch and bound from the ants' clique for at most that many nodes: a
    proof of maximality or a heavier clique; 0: none), backend (auto, serial, omp, tbb),
    threads, and the engine's parameters (ants, rho, ...). The run also stops when a clique
    reaches the colouring bound (stop_reason "target": proven maximum)."""
    settings = _core.clique.AcoSettings()
    if variant is not None:
        settings.parameters.variant = variant
    settings.parameters.seed = seed
    engine = {k: options.pop(k) for k in list(options) if k in _options.ENGINE}
    stop = {k: options.pop(k) for k in list(options) if k in _STOP}
    _options.apply(settings.parameters, _options.ENGINE, engine, "aco")
    _options.apply(settings.termination, _STOP, stop, "aco")
    _options.apply(settings, _SEARCH, options, "aco")
    try:
        clique, iterations, reason = _core.clique.aco(graph, settings)
    except _core.Interrupted as stopped:
        stopped.result = AcoResult(*stopped.result)
        raise
    return AcoResult(clique, iterations, reason)


def exact(graph, time_limit=60.0):
    """The maximum clique by branch and bound with colouring bounds; when time_limit (s; 0:
    none) ends the search first, the best clique found, with optimal False."""
    clique, _ = _core.clique.exact(graph, float(time_limit))
    return clique


def greedy(graph):
    """A maximal clique, greedily: the baseline the searches must beat."""
    return _core.clique.greedy(graph)
