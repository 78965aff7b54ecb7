"""The result of a colony run as Python sees it."""
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Run:
    """What a colony run found and what ran (aco::RunResult)."""
    cost: float           #: the best cost
    path: np.ndarray      #: the best path: a tour, or one option per layer
    iterations: int       #: iterations run
    best_iteration: int   #: iteration that found the best
    elapsed_s: float      #: wall-clock seconds of the run
    time_to_best_s: float  #: wall-clock seconds until the best was found
    stop_reason: str      #: iterations, time, cpu-time, target, stagnation or interrupted
    variant: str          #: the ACO variant that ran
    ants: int             #: ants per iteration, default resolved
    rho: float            #: evaporation rate, default resolved
    backend: str          #: serial, omp or tbb
    threads: int          #: threads that built the ants

    @classmethod
    def of(cls, run):
        return cls(run.cost, run.path, run.iterations, run.best_iteration, run.elapsed_s,
                   run.time_to_best_s, run.stop_reason, run.variant, run.ants, run.rho,
                   run.backend, run.threads)
