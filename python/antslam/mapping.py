"""The whole AntSLAM pipeline on a CARMEN laser log in one call, as `antslam map` runs it
(mapping/pipeline.hpp): frontend, fragment set, optimizer trials, corrected trajectory, maps and
the evaluation against a reference.

    r = antslam.mapping.run_pipeline("data/laser/malaga-oneloop.clf", laser_offset=0.78,
                                     trials=4, draw_maps=False)
    r.trajectory          # (n, 4): t, x, y, theta of every scan, corrected
    r.closures            # Mahalanobis distance of every loop closure before and after
"""
import math
import os

from . import _core, _options
from .slam import _OPTIMIZER

# Options of `antslam map` by their names here, and the settings attribute each one sets.
_PIPELINE = dict(
    {name: "mapping.optimize." + path for name, path in _OPTIMIZER.items()},
    trials="mapping.trials", threads="mapping.threads", draw_maps="draw_maps",
    resolution="resolution", fragment_length="frontend.fragment_length",
    samples="frontend.samples", alignment="frontend.alignment",
    covariance_scale="frontend.covariance_scale", temperature="frontend.temperature",
    closures="frontend.closures", closure_min_score="frontend.closure_min_score",
    closure_max_second="frontend.closure_max_second",
    closure_temperature="frontend.closure_temperature", max_range="sensor.max_range",
    laser_offset="sensor.laser_offset")


def pipeline_settings(**options):
    """The settings of `antslam map` with the given options (see run_pipeline)."""
    s = _core.mapping.PipelineSettings()
    s.mapping.threads = 0  # as the program: all cores for the trials
    angles = {k: options.pop(k) for k in ("fov", "first_beam") if k in options}
    _options.apply(s, _PIPELINE, options, "run_pipeline")
    if "fov" in angles:
        s.sensor.field_of_view = math.radians(angles["fov"])
    if "first_beam" in angles:
        s.sensor.first_angle = math.radians(angles["first_beam"])
    s.mapping.backend = s.mapping.optimize.backend
    s.frontend.seed = s.mapping.optimize.seed
    return s


def run_pipeline(log, reference=None, *, observer=None, **options):
    """Runs the pipeline on a CARMEN log (.clf/.log, may be gzipped); `reference`: a TUM file to
    evaluate both trajectories against. observer(stage, final) hears the progress lines.

    Options, as the antslam map options: laser_offset, max_range (metres), fov, first_beam
    (degrees), fragment_length, samples, alignment (accumulated, exit-scan), covariance_scale,
    temperature, closures (False: none), closure_min_score, closure_max_second,
    closure_temperature, trials, threads (0: all cores; results do not depend on it),
    draw_maps, resolution, and every option of antslam.slam.optimize (method defaults to
    hybrid+nlopt). Returns a PipelineResult: fragment_set, trajectory, scan_matcher_trajectory,
    trials, best_trial, scan_matcher_scores, closures, evaluation, times, maps, report()."""
    settings = pipeline_settings(**options)
    reference = None if reference is None else os.fspath(reference)
    return _core.mapping.run_pipeline_settings(os.fspath(log), settings, reference, observer)
