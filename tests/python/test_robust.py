"""antslam.slam's false closures and robust back ends: the same spoiled graph, decisions and
optimised graph as `antslam outliers` and `antslam robust`, the decisions against the known
false closures, and bad input."""
import numpy as np
import pytest

import antslam
from conftest import DATA, SOURCE

RING = DATA / "posegraphs" / "ring.g2o"
BAD = SOURCE / "tests" / "app" / "robust"


@pytest.fixture(scope="module")
def spoiled():
    graph = antslam.slam.read_graph(RING)
    return antslam.slam.add_outliers(graph, 20, kind="random-group", group_size=5, seed=3)


def test_the_spoiled_graph_is_the_programs(spoiled, program, tmp_path):
    graph, false = spoiled
    program("outliers", RING, "--count", 20, "--kind", "random-group", "--group-size", 5,
            "--seed", 3, "-o", tmp_path / "ring20.g2o")
    graph.save(tmp_path / "python.g2o")
    assert (tmp_path / "python.g2o").read_bytes() == (tmp_path / "ring20.g2o").read_bytes()
    np.testing.assert_array_equal(false, np.loadtxt(tmp_path / "ring20.outliers.txt"))
    assert false.shape == (20, 2) and len(graph) == 434


@pytest.mark.parametrize("method", ["pcm-aco", "pcm-exact"])
def test_pcm_keeps_every_true_closure_and_no_false_one(spoiled, method):
    graph, false = spoiled
    r = antslam.slam.robust(graph, method)
    assert r.method == method and r.poses.shape == (434, 3)
    assert len(r.closures) == len(r.accepted) == 46  # 26 true, 20 false
    false_pairs = {tuple(p) for p in false.tolist()}
    kept = {tuple(c) for c in r.closures[r.accepted].tolist()}
    assert len(kept) == 26 and not kept & false_pairs
    assert r.clique.weight == 26 and r.consistent_pairs > 0
    assert repr(r).startswith(f"<antslam.slam.RobustResult {method}: 26 of 46 loop closures accepted, ")


def test_the_recalibrated_check_reports_its_factor_and_core(spoiled):
    graph, false = spoiled
    never = antslam.slam.robust(graph, "pcm-aco", recalibrate_below=0)
    r = antslam.slam.robust(graph, "pcm-aco", recalibrate_below=1e9)
    assert never.core is None and never.variance_factor == r.variance_factor
    assert 0 < r.variance_factor < 1 and r.core.weight <= len(r.closures)
    default = antslam.slam.robust(graph, "pcm-aco")
    assert (default.core is not None) == (default.variance_factor < 0.13)
    false_pairs = {tuple(p) for p in false.tolist()}
    assert not {tuple(c) for c in r.closures[r.accepted].tolist()} & false_pairs


def test_the_check_reports_the_phi_it_took_from_the_noise_the_clique_shows(spoiled):
    graph, _ = spoiled
    r = antslam.slam.robust(graph, "pcm-aco", check_phi=2.0)
    fixed = antslam.slam.robust(graph, "pcm-aco", check_phi=0, dcs_phi=0.5)
    assert fixed.check_phi == 0.5
    assert antslam.slam.robust(graph, "pcm-aco").check_phi == 1.0  # DCS's Phi by default
    assert r.check_phi > 0 and r.check_phi == pytest.approx(
        2 * antslam.slam.robust(graph, "pcm-aco", check_phi=1).check_phi)
    assert antslam.slam.robust(graph, "ls").check_phi is None
    with pytest.raises(ValueError, match="check's Phi"):
        antslam.slam.robust(graph, "pcm-aco", check_phi=-1)


def test_least_squares_accepts_everything(spoiled):
    r = antslam.slam.robust(spoiled[0], "ls")
    assert r.accepted.all() and r.clique is None and r.consistent_pairs is None


def test_the_decisions_and_the_graph_are_the_programs(spoiled, program, tmp_path):
    graph, _ = spoiled
    graph.save(tmp_path / "ring20.g2o")
    program("robust", tmp_path / "ring20.g2o", "--method", "pcm-aco", "--plateau-steps", 10,
            "--seed", 4, "-o", tmp_path / "program")
    r = antslam.slam.robust(graph, "pcm-aco", plateau_steps=10, seed=4)
    np.testing.assert_array_equal(r.closures[r.accepted],
                                  np.loadtxt(tmp_path / "program.accepted.txt"))
    r.kept_graph(graph).save(tmp_path / "python.g2o")
    assert (tmp_path / "python.g2o").read_bytes() == (tmp_path / "program.g2o").read_bytes()


def test_bad_input_is_one_line(spoiled):
    graph, _ = spoiled
    with pytest.raises(ValueError, match=r"method: unknown 'magic' \(expected one of ls, "):
        antslam.slam.robust(graph, "magic")
    with pytest.raises(TypeError, match="unexpected keyword argument 'plateau'"):
        antslam.slam.robust(graph, plateau=1)
    with pytest.raises(ValueError, match="inlier confidence must be in"):
        antslam.slam.robust(graph, confidence=2.0)
    with pytest.raises(ValueError, match="kind: unknown 'far'"):
        antslam.slam.add_outliers(graph, 5, kind="far")
    with pytest.raises(ValueError, match="groups of 1000000 need 1000003"):
        antslam.slam.add_outliers(graph, 5, kind="random-group", group_size=10**6)
    alone = antslam.slam.read_graph(BAD / "one-pose-session.g2o")
    with pytest.raises(RuntimeError, match=r"one-pose-session\.g2o: vertex 3 has no edge to the"):
        antslam.slam.robust(alone)
    two_sessions = antslam.slam.read_graph(BAD / "broken-chain.g2o")
    assert antslam.slam.robust(two_sessions).accepted.tolist() == [True]


def test_the_consistency_graph_is_the_one_pcm_searches(spoiled):
    graph, false = spoiled
    c = antslam.slam.consistency(graph)
    r = antslam.slam.robust(graph, "pcm-aco", check_clique=False)
    np.testing.assert_array_equal(c.closures, r.closures)
    assert len(c.graph) == 46 and c.threshold == pytest.approx(11.344866730144)  # chi2(3), 0.99
    assert antslam.clique.aco(c.graph).vertices.tolist() == r.clique.vertices.tolist()
    best = antslam.clique.exact(c.graph)
    assert best.optimal and best.weight == 26
    false_pairs = {tuple(p) for p in false.tolist()}
    assert not {tuple(c.closures[k]) for k in best.vertices} & false_pairs


def test_the_consistency_graph_keeps_its_invariants(spoiled):
    graph, _ = spoiled
    c = antslam.slam.consistency(graph, threads=2)
    strict = antslam.slam.consistency(graph, confidence=0.01)
    assert strict.threshold == pytest.approx(0.114831801899)  # chi2(3), 0.01
    n = len(c.graph)
    edges = {(k, l) for k in range(n) for l in range(k + 1, n) if c.graph.adjacent(k, l)}
    strict_edges = {(k, l) for k in range(n) for l in range(k + 1, n)
                    if strict.graph.adjacent(k, l)}
    assert strict_edges < edges  # a stricter test keeps a subset of the pairs
    assert all(c.graph.adjacent(l, k) for k, l in edges)
    # a closure that disagrees with the odometry between its ends has no consistent pair
    lone = [k for k in range(n) if not c.odometry_consistent[k]]
    assert lone and not any(k in pair for pair in edges for k in lone)
    with pytest.raises(ValueError, match="confidence"):
        antslam.slam.consistency(graph, confidence=1.5)


def narrowed(path, factor, out):
    """The g2o graph at `path` with every information matrix times `factor`, written to `out`."""
    lines = []
    for line in path.read_text().splitlines():
        fields = line.split()
        if fields and fields[0] == "EDGE_SE2":
            fields[6:12] = [repr(float(v) * factor) for v in fields[6:12]]
        lines.append(" ".join(fields))
    out.write_text("\n".join(lines) + "\n")
    return out


def test_robust_reports_the_noise_the_graph_shows(tmp_path):
    graph = antslam.slam.read_graph(RING)
    default = antslam.slam.robust(graph, "pcm-aco")
    shown = antslam.slam.robust(graph, "pcm-aco", shown_noise=True)
    stated = antslam.slam.robust(graph, "pcm-aco", widen_noise=False)
    assert stated.noise_scale is None and stated.widened is None
    xy, theta = shown.noise_scale
    assert 0 < xy < 1 and 0 < theta < 1  # ring states its noise wider than it shows
    assert default.noise_scale == shown.noise_scale  # estimated, but not widened
    assert default.widened is None and list(default.accepted) == list(stated.accepted)
    # x-y stated 20 times narrower: about 8 times narrower than shown, the heading still wider
    narrow = narrowed(RING, 400.0, tmp_path / "narrow.g2o")
    widened = antslam.slam.robust(antslam.slam.read_graph(narrow), "pcm-aco").widened
    assert widened is not None and widened[0] == pytest.approx(20 * xy, rel=0.2)
    assert widened[1] == 1
    assert antslam.slam.robust(graph, "gnc").noise_scale is None
