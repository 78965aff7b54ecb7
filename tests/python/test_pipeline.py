"""antslam.mapping: the pipeline on the bundled one-loop log in one call, as `antslam map` runs
it with the same options."""
import json

import numpy as np
import pytest

import antslam
from conftest import DATA

LOG = DATA / "laser" / "malaga-oneloop.clf"
OPTIONS = dict(laser_offset=0.78, trials=2, iterations=300, threads=2)


@pytest.fixture(scope="module")
def run():
    stages = []
    result = antslam.mapping.run_pipeline(LOG, draw_maps=False,
                                          observer=lambda stage, final: stages.append(stage),
                                          **OPTIONS)
    return result, stages


def test_the_pipeline_closes_the_loop(run):
    r, stages = run
    assert r.scans == 225 and len(r.fragment_set) == 16
    assert r.trajectory.shape == (225, 4) and r.scan_matcher_trajectory.shape == (225, 4)
    assert len(r.trials) == 2 and r.best_trial in (0, 1)
    assert repr(r).startswith(f"<antslam.mapping.PipelineResult of {LOG}: 225 scans, 16 fragments, ")
    assert " loop closures, 2 trials, weight " in repr(r)
    assert r.trials[r.best_trial].weight < r.scan_matcher_scores[0]
    assert all(c["after_sigmas"] <= 2.0 for c in r.closures)
    assert r.maps is None and r.evaluation is None
    assert stages and r.times["total_s"] > 0
    report = json.loads(r.report())
    assert report["optimization"]["method"] == "hybrid+nlopt"


def test_same_trajectory_as_the_program(run, program, tmp_path):
    r, _ = run
    program("map", LOG, "--laser-offset", 0.78, "--trials", 2, "--iterations", 300,
            "--threads", 2, "--no-maps", "--out-dir", tmp_path)
    expected = antslam.eval.read_tum(tmp_path / "trajectory.tum")
    np.testing.assert_allclose(r.trajectory[:, 1:3], expected[:, 1:3], atol=1e-8)
    np.testing.assert_allclose(r.trajectory[:, 0], expected[:, 0], atol=1e-6)


def test_maps_and_evaluation():
    r = antslam.mapping.run_pipeline(DATA / "laser" / "intel-subset.clf",
                                     DATA / "laser" / "intel-subset.ref.tum", trials=1,
                                     iterations=50, resolution=0.2, method="ceres")
    assert set(r.maps) == {"scan_matcher", "optimized", "average"}
    image = r.maps["optimized"]
    assert image.dtype == np.uint8 and image.ndim == 3 and image.shape[2] == 3
    e = r.evaluation["optimized"]
    assert e.ate.translation_m.rmse < r.evaluation["scan_matcher"].ate.translation_m.rmse


def test_errors_are_one_line(tmp_path):
    with pytest.raises(RuntimeError, match=r"missing\.clf: cannot open"):
        antslam.mapping.run_pipeline(tmp_path / "missing.clf")
    with pytest.raises(ValueError, match=r"trials must be >= 1"):
        antslam.mapping.run_pipeline(LOG, trials=0)
    with pytest.raises(ValueError, match=r"found no loop closure in 16 fragments"):
        antslam.mapping.run_pipeline(LOG, laser_offset=0.78, closures=False)
    with pytest.raises(TypeError, match=r"^run_pipeline\(\) got an unexpected keyword"):
        antslam.mapping.run_pipeline(LOG, trails=3)
