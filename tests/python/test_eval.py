"""antslam.eval: ATE, RPE and the relations metric of numpy trajectories and TUM files, against
hand-computed values and the antslam eval program."""
import json

import numpy as np
import pytest

import antslam
from conftest import DATA


def square_walk(n=20):
    t = np.arange(n, dtype=float)
    return np.column_stack([t, np.cos(t / 3), np.sin(t / 3), t / 3 + np.pi / 2])


def test_a_shifted_copy_has_the_shift_as_ate_without_alignment_and_none_with_it():
    reference = square_walk()
    estimate = reference.copy()
    estimate[:, 1] += 1.0  # one metre along x
    e = antslam.eval.evaluate(estimate, reference, align=False)
    assert e.associated == 20
    assert e.ate.translation_m.rmse == pytest.approx(1.0, abs=1e-12)
    assert repr(e) == "<antslam.eval.Evaluation of 20 associated poses: ATE 1 m rmse, 1 m max>"
    assert e.rpe.translation_m.max == pytest.approx(0.0, abs=1e-12)  # relative motion unchanged
    e = antslam.eval.evaluate(estimate, reference)
    assert e.ate.translation_m.rmse == pytest.approx(0.0, abs=1e-9)
    assert antslam.eval.frames_error(estimate[:, 1:], reference[:, 1:]).rmse_m == pytest.approx(
        0.0, abs=1e-9)


def test_files_arrays_and_the_program_agree(program, tmp_path):
    reference = DATA / "laser" / "intel-subset.ref.tum"
    ref = antslam.eval.read_tum(reference)
    estimate = ref.copy()
    estimate[:, 1] += 0.01 * np.sin(np.arange(len(ref)))
    antslam.eval.write_tum(tmp_path / "e.tum", estimate)
    np.testing.assert_allclose(antslam.eval.read_tum(tmp_path / "e.tum"), estimate, atol=1e-6)
    program("eval", tmp_path / "e.tum", reference, "--relations", DATA / "laser" / "intel.relations",
            "--json", tmp_path / "e.json")
    expected = json.loads((tmp_path / "e.json").read_text())
    e = antslam.eval.evaluate(tmp_path / "e.tum", reference, relations=DATA / "laser" / "intel.relations")
    mine = json.loads(e.to_json())
    del expected["relations"]["file"]  # the program names its input files; to_json() does not
    for key in ("ate", "rpe", "relations"):
        assert mine[key] == expected[key]
    assert e.relations.used > 50


def test_errors_are_one_line(tmp_path):
    a = square_walk()
    b = a.copy()
    b[:, 0] += 1000.0
    with pytest.raises(ValueError, match=r"^no estimated pose has a reference pose within max_dt = 0\.02 s "):
        antslam.eval.evaluate(a, b)
    with pytest.raises(ValueError, match=r"^estimate: expected an \(n, 4\) array of \(t, x, y, theta\)$"):
        antslam.eval.evaluate(a[:, :3], a)
    bad = a.copy()
    bad[3, 2] = np.inf
    with pytest.raises(ValueError, match=r"^reference: row 3 is not finite$"):
        antslam.eval.evaluate(a, bad)
    with pytest.raises(RuntimeError, match=r"missing\.tum: cannot open"):
        antslam.eval.evaluate(tmp_path / "missing.tum", a)
    with pytest.raises(TypeError, match=r"^evaluate\(\) got an unexpected keyword argument 'rpe'$"):
        antslam.eval.evaluate(a, a, rpe=3)
