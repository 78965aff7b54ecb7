"""TSPLIB instances and the ACO solver, as `antslam tsp` runs them (tsp/solver.hpp).

    instance = antslam.tsp.read("data/tsplib/berlin52.tsp")
    result = antslam.tsp.solve(instance, variant="acs", iterations=100, seed=1,
                               local_search="2opt", threads=2)
    result.length, result.tour            # a float and a permutation of 0..n-1 (numpy)

Instances of your own: `Instance(coords, edge_weight_type="EUC_2D", name="python")` from an
(n, 2) array, `Instance.from_matrix(matrix, name="python")` from a symmetric (n, n) array of
whole distances; both pickle and save as TSPLIB files.
"""
import os
from dataclasses import dataclass

import numpy as np

from . import _core, _options
from ._runs import Run

Instance = _core.tsp.Instance


def read(path):
    """Reads a TSPLIB instance (EUC_2D, CEIL_2D, ATT, GEO or EXPLICIT)."""
    return _core.tsp.read(os.fspath(path))


def generate(cities, seed=1, side=1.0e6):
    """Random uniform EUC_2D instance: integer coordinates in [0, side]^2."""
    return _core.tsp.generate(cities, seed, side)


def known_optimum(path):
    """The optimum of an instance listed in optima.csv beside it, or None."""
    return _core.tsp.known_optimum(os.fspath(path))


@dataclass(frozen=True)
class Result(Run):
    """A TSP run: `length` and `tour` are the best tour's, the rest as in Run."""
    @property
    def length(self):
        return self.cost

    @property
    def tour(self):
        return self.path


# Options beyond the engine's parameters, and the settings attribute each one sets.
_SOLVER = {"local_search": "local_search", "ls_start": "ls_start", "backend": "backend",
           "threads": "threads", "hybrid_deposit": "hybrid_deposit",
           "focused_edges": "focused_edges", "two_level_from": "two_level_from"}
_PROBLEM = {"candidates": "candidates", "matrix_limit": "matrix_limit"}


def solve(instance, variant="mmas", iterations=200, seed=3, *, local_search="3opt",
          neighbours=20, time_limit=0.0, cpu_time_limit=0.0, target=None, stagnation=0,
          observer=None, colonies=1, exchange_every=25, topology="ring", **options):
    """Solves the instance with an ACO variant (as, eas, ras, acs, mmas, hybrid).

    local_search: none, 2opt, 2.5opt, 3opt; neighbours: cities the local search tries per city.
    Stop criteria: iterations (0: none), time_limit and cpu_time_limit (seconds), target (a
    length), stagnation (iterations without a better tour). observer(info) is called after every
    iteration with an antslam.aco.IterationInfo (iteration, elapsed_s, iteration_best,
    global_best, improved, best). Further options, as the antslam tsp options of the same name:
    ants, alpha, beta, rho, q0, xi, elite_weight, rank_width, p_best, restarts, p0,
    glob_best_freq, tau_max, tau_init, hybrid_deposit, ls_ants, ls_start, two_level_from,
    candidates, matrix_limit, backend (auto, serial, omp, tbb), threads, focused_edges (new
    edges per focused ant, Skinderowicz 2022; 0: every tour built from nothing; default 8 for
    mmas, 0 for the other variants). Zero means the variant's default
    where the program says so. colonies > 1: the island model in this process (docs/mpi-islands.md),
    colonies exchanging their best tours every exchange_every iterations along topology (ring,
    full); the observer's `best` is then empty. The same options and seed give the program's
    tour."""
    settings = _core.tsp.SolverSettings()
    problem = _core.tsp.ProblemSettings()
    parameters = {k: options.pop(k) for k in list(options) if k in _options.ENGINE}
    solver = {k: options.pop(k) for k in list(options) if k in _SOLVER}
    _options.apply(problem, _PROBLEM, options, "solve")
    settings.aco.variant = variant
    settings.aco.seed = seed
    _options.apply(settings.aco, _options.ENGINE, parameters, "solve")
    _options.apply(settings, _SOLVER, dict(solver, local_search=local_search), "solve")
    settings.ls_neighbours = neighbours
    problem.ls_neighbours = neighbours
    try:
        run = _core.tsp.solve_settings(
            instance, settings, problem,
            _options.termination(iterations, time_limit, cpu_time_limit, target, stagnation),
            observer, colonies, exchange_every, topology)
    except _core.Interrupted as stopped:
        stopped.result = Result.of(stopped.result)
        raise
    return Result.of(run)
