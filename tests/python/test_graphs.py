"""antslam.slam on pose graphs as the benchmark sets have them: files without vertices, two
sessions, TORO lines, FIX lines; least squares and NLopt on the graph, the ants on its chain;
the program's result for the same options."""
import numpy as np
import pytest

import antslam
from conftest import DATA, GRAPHS


def test_a_file_without_vertices_gets_its_poses_from_the_odometry():
    g = antslam.slam.read_graph(GRAPHS / "edges-only.g2o")
    assert not g.vertices_from_file and len(g) == 4
    # Unit steps turning left by 90 degrees: three corners of the unit square.
    np.testing.assert_allclose(g.vertices[:, :2], [[0, 0], [1, 0], [1, 1], [0, 1]], atol=1e-6)
    r = antslam.slam.optimize(g, method="ceres")
    assert r.chi2 < g.score(g.vertices)[1]


def test_two_sessions_by_least_squares_and_nlopt_not_by_the_ants():
    g = antslam.slam.read_graph(GRAPHS / "two-sessions.g2o")
    ceres = antslam.slam.optimize(g, method="ceres")
    nlopt = antslam.slam.optimize(g, method="nlopt", max_evaluations=5000)
    assert ceres.weight < 0.05 and nlopt.weight < 0.05
    np.testing.assert_array_equal(ceres.frames[0], g.vertices[0])  # the anchor stays
    # Session 2 moves from half a metre off onto its corridor 2 m above session 1.
    np.testing.assert_allclose(ceres.frames[3:, 1], 2.0, atol=0.05)
    with pytest.raises(ValueError, match=r"no edge between vertices 2 and 3: the ant methods"):
        antslam.slam.optimize(g, method="mmas")


def test_toro_files_read_and_write_both_formats(tmp_path):
    g = antslam.slam.read_graph(GRAPHS / "square.graph")
    g.save(tmp_path / "square.g2o")
    g.save(tmp_path / "square-again.graph")
    assert (tmp_path / "square.g2o").read_text().count("EDGE_SE2") == 4
    assert (tmp_path / "square-again.graph").read_text().count("EDGE2") == 4
    for path in ("square.g2o", "square-again.graph"):
        again = antslam.slam.read_graph(tmp_path / path)
        np.testing.assert_array_equal(again.information, g.information)
        np.testing.assert_array_equal(again.vertices, g.vertices)


def test_fixed_vertices_stay_where_the_file_puts_them():
    g = antslam.slam.read_graph(GRAPHS / "fixed.g2o")
    assert g.fixed == [0, 2]
    r = antslam.slam.optimize(g, method="ceres")
    np.testing.assert_array_equal(r.frames[[0, 2]], g.vertices[[0, 2]])
    g.fixed = [1]
    r = antslam.slam.optimize(g, method="hybrid", iterations=100, samples=5)
    np.testing.assert_allclose(r.frames[1], g.vertices[1], atol=1e-12)
    with pytest.raises(ValueError, match=r"^fixed: vertex 9 is not in the graph$"):
        g.fixed = [9]


def test_the_benchmark_graph_as_the_program_optimizes_it(program, tmp_path):
    ring = DATA / "posegraphs" / "ring.g2o"
    program("optimize", ring, "--method", "ceres", "-o", tmp_path / "r", "--g2o-out",
            tmp_path / "r.g2o")
    r = antslam.slam.optimize(antslam.slam.read_graph(ring), method="ceres")
    written = antslam.slam.read_graph(tmp_path / "r.g2o").vertices
    np.testing.assert_array_equal(written, r.frames)
    assert r.chi2 == pytest.approx(11.1631, abs=1e-4)  # as docs/slamgraph-results.md


def test_bad_graphs_are_one_line():
    with pytest.raises(RuntimeError, match=r"bad-fix\.g2o:3: 'banana' is not a vertex id$"):
        antslam.slam.read_graph(GRAPHS / "bad-fix.g2o")
    with pytest.raises(RuntimeError, match=r"se3\.g2o:1: 'VERTEX_SE3:QUAT' is a 3D type"):
        antslam.slam.read_graph(GRAPHS / "se3.g2o")
    g = antslam.slam.read_graph(GRAPHS / "square.graph")
    with pytest.raises(ValueError, match=r"^vertices: got 2 poses for 4 vertices$"):
        g.vertices = np.zeros((2, 3))


def test_from_g2o_is_the_programs_fragment_set(program, tmp_path):
    ring = DATA / "posegraphs" / "ring.g2o"
    program("g2o", ring, "-o", tmp_path / "ring.json", "-m", 5, "--seed", 2)
    expected = antslam.slam.load(tmp_path / "ring.json")
    s = antslam.slam.from_g2o(ring, samples=5, seed=2)
    assert len(s) == len(antslam.slam.read_graph(ring)) == len(expected)
    assert s.closures == expected.closures and len(s.closures) > 0
    np.testing.assert_array_equal(s.means, expected.means)
    for fragment in (1, len(s) // 2, len(s) - 1):
        assert s.samples(fragment).shape == (5, 3)
        np.testing.assert_array_equal(s.samples(fragment), expected.samples(fragment))
    # The same from a graph already read, and a different seed draws different samples.
    again = antslam.slam.from_g2o(antslam.slam.read_graph(ring), samples=5, seed=2)
    np.testing.assert_array_equal(again.samples(1), s.samples(1))
    assert not np.array_equal(antslam.slam.from_g2o(ring, samples=5, seed=3).samples(1),
                              s.samples(1))
