"""Trajectory evaluation as `antslam eval` reports it (eval/evaluation.hpp): association by
timestamp, rigid alignment, the absolute trajectory error (ATE), the relative pose error (RPE)
and, given relations, the metric of Kuemmerle et al. 2009. Trajectories are (n, 4) arrays of
(t, x, y, theta) or TUM files.

    e = antslam.eval.evaluate("estimate.tum", "data/laser/mit-csail.ref.tum")
    e.ate.translation_m.rmse, e.rpe.rotation_deg.mean
"""
import os

import numpy as np

from . import _core, _options

Evaluation = _core.eval.Evaluation


def read_tum(path):
    """A TUM trajectory file as an (n, 4) array of (t, x, y, theta)."""
    return _core.eval.read_tum(os.fspath(path))


def write_tum(path, trajectory):
    """Writes an (n, 4) trajectory as a TUM file (atomically)."""
    _core.eval.write_tum(os.fspath(path), np.asarray(trajectory, dtype=np.float64))


def _trajectory(value):
    if isinstance(value, (str, os.PathLike)):
        t = read_tum(value)
        if len(t) == 0:
            raise RuntimeError(f"{os.fspath(value)}: no poses")
        return t
    return np.asarray(value, dtype=np.float64)


_SETTINGS = {"max_dt": "max_dt", "align": "align", "rpe_frames": "rpe.frames",
             "rpe_distance": "rpe.metres", "relations_max_dt": "relations_max_dt"}


def evaluate(estimate, reference, *, relations=None, **options):
    """ATE, RPE and (with a relations file) the relations metric of `estimate` against
    `reference`. Options as the antslam eval options: max_dt (s), align (False: no rigid
    alignment), rpe_frames, rpe_distance (metres; 0: rpe_frames), relations_max_dt (s)."""
    settings = _core.eval.EvaluationSettings()
    _options.apply(settings, _SETTINGS, options, "evaluate")
    return _core.eval.evaluate_arrays(_trajectory(estimate),
                                      _trajectory(reference), settings,
                                      None if relations is None else os.fspath(relations))


def frames_error(frames, reference):
    """Poses without timestamps (e.g. an optimizer's frames, (n, 3)) against reference poses of
    the same index, after rigid alignment: rmse_m, max_m, rmse_deg, poses."""
    return _core.eval.frames_error(np.asarray(frames, dtype=np.float64),
                                   np.asarray(reference, dtype=np.float64))
