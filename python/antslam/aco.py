"""The colony engine on your own layered-choice problem, from tables (no C++): one option per
layer, and the cost of a choice c = (c_0, ..., c_{L-1})

    cost(c) = sum_l costs[l][c_l] + sum_l pairwise[l][c_l, c_{l+1}] + term(c)

where `pairwise` couples consecutive layers and `term` is any Python function of the whole
choice (a numpy uint32 array). Every variant runs on it, with any backend and thread count;
a seed gives the same choice on every one.

    import numpy as np, antslam
    costs = np.random.default_rng(1).random((8, 5))     # 8 layers, 5 options each
    r = antslam.aco.solve(costs, term=lambda c: float(c.sum() % 3), variant="acs",
                          iterations=100, seed=2)
    r.cost, r.choice
"""
from dataclasses import dataclass

import numpy as np

from . import _core, _options
from ._runs import Run

IterationInfo = _core.aco.IterationInfo
VARIANTS = tuple(_core.aco.variant_names())
BACKENDS = tuple(name.strip() for name in _core.aco.backend_names().split(","))


@dataclass(frozen=True)
class Result(Run):
    """A layered run: `choice` is the best option of every layer, the rest as in Run."""
    @property
    def choice(self):
        return self.path


def _rows(table, name):
    """A 2D array, or a sequence of 1D arrays (layers of different sizes), as float64 rows."""
    if isinstance(table, np.ndarray) and table.ndim == 2:
        return [np.ascontiguousarray(row, dtype=np.float64) for row in table]
    rows = [np.ascontiguousarray(row, dtype=np.float64) for row in table]
    for k, row in enumerate(rows):
        if row.ndim != 1:
            raise ValueError(f"{name}[{k}]: expected a one-dimensional array of option values")
    return rows


def _pair_tables(pairwise, costs):
    """One (options of l) x (options of l + 1) table per consecutive pair, flattened."""
    tables = [np.ascontiguousarray(t, dtype=np.float64) for t in pairwise]
    for k, t in enumerate(tables):
        if k + 1 < len(costs) and t.shape != (len(costs[k]), len(costs[k + 1])):
            raise ValueError(f"pairwise[{k}]: expected shape ({len(costs[k])}, "
                             f"{len(costs[k + 1])}), got {t.shape}")
    return [t.ravel() for t in tables]


def solve(costs, pairwise=None, term=None, *, heuristic=None, variant="mmas", iterations=200,
          seed=1, time_limit=0.0, cpu_time_limit=0.0, target=None, stagnation=0,
          backend="auto", threads=1, observer=None, **parameters):
    """Runs an ACO variant on the layered problem of the tables (module doc).

    costs: an (L, K) array or L one-dimensional arrays (layers may differ in size); pairwise:
    None, an (L - 1, K, K) array or L - 1 tables; term: None or f(choice) -> float; heuristic:
    None or desirabilities of costs' shape (eta of eq. 1, 1 when None). Tables and term must be
    >= 0: the engine deposits q / cost (add a constant to a layer to shift it; the best choice
    stays). term runs on the ants' threads with the GIL held (a pure function gives the same
    result on any thread count); an exception in it stops the run and is raised. Parameters as
    in antslam.tsp.solve: ants, alpha, beta, rho, q0, xi, elite_weight, rank_width, p_best,
    restarts, p0, glob_best_freq, tau_max, tau_init."""
    unary = _rows(costs, "costs")
    pairs = [] if pairwise is None else _pair_tables(pairwise, unary)
    eta = [] if heuristic is None else _rows(heuristic, "heuristic")
    p = _core.aco.Parameters()
    p.variant = variant
    p.seed = seed
    _options.apply(p, _options.ENGINE, parameters, "solve")
    try:
        run = _core.aco.solve_layered(
            unary, pairs, eta, term, p,
            _options.termination(iterations, time_limit, cpu_time_limit, target, stagnation),
            backend, threads, observer)
    except _core.Interrupted as stopped:
        stopped.result = Result.of(stopped.result)
        raise
    return Result.of(run)


def brute_force(costs, pairwise=None, term=None):
    """The exact minimum by enumerating every choice (small problems; for checking the ants):
    (cost, choice)."""
    unary = _rows(costs, "costs")
    pairs = [] if pairwise is None else [np.asarray(t, dtype=np.float64) for t in pairwise]
    best, best_choice = np.inf, None
    for flat in np.ndindex(*[len(row) for row in unary]):
        choice = np.array(flat, dtype=np.uint32)
        cost = sum(unary[l][c] for l, c in enumerate(choice))
        cost += sum(pairs[l][choice[l], choice[l + 1]] for l in range(len(pairs)))
        if term is not None:
            cost += term(choice)
        if cost < best:
            best, best_choice = cost, choice
    return best, best_choice
