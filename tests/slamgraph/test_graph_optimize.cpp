// The optimizers on pose graphs as files give them: the edges as stored, the vertex estimates as
// the start, the fixed vertices where the file puts them, several sessions.

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <functional>
#include <numbers>
#include <sstream>

#include "antslam/slamgraph/graph_objective.hpp"
#include "antslam/slamgraph/graph_optimize.hpp"
#include "antslam/slamgraph/graph_structure.hpp"
#include "support.hpp"

namespace antslam::slam {
namespace {

struct Truth {
  PoseGraph graph;           // vertices perturbed, edges exact (unless noise)
  std::vector<Pose2> poses;  // the poses the edges were measured between
};

/// n poses on a noisy circle, odometry edges (some stored backwards) and closures between random
/// pairs, each exact; the vertex estimates perturbed by up to `perturbation` (metres, radians).
/// With `sessions`, the odometry edge between n/2 - 1 and n/2 is left out.
Truth random_graph(std::size_t n, std::size_t closures, std::uint64_t seed, double perturbation,
                   bool sessions = false) {
  aco::Rng rng(aco::mix_seed(seed, 91));
  Truth t;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    t.poses.push_back({5.0 * std::cos(a) + 0.3 * rng.uniform(), 5.0 * std::sin(a),
                       wrap_angle(a + 1.5 + 0.2 * rng.uniform())});
  }
  const auto add = [&](std::size_t i, std::size_t j) {
    const Eigen::Matrix3d information = testing::random_covariance(rng, 1.0).inverse();
    t.graph.edges.push_back({i, j, between(t.poses[i], t.poses[j]), information});
  };
  for (std::size_t i = 1; i < n; ++i) {
    if (sessions && i == n / 2) continue;
    if (i % 3 == 0) {
      add(i, i - 1);
    } else {
      add(i - 1, i);
    }
  }
  for (std::size_t c = 0; c < closures; ++c) {
    const std::size_t b = 2 + rng.below(static_cast<std::uint32_t>(n - 2));
    add(b, rng.below(static_cast<std::uint32_t>(b - 1)));
  }
  for (const Pose2& p : t.poses)
    t.graph.vertices.push_back(Pose2::from_vector(
        p.vector() + perturbation * Eigen::Vector3d(rng.uniform() - 0.5, rng.uniform() - 0.5,
                                                    rng.uniform() - 0.5)));
  t.graph.vertices[0] = t.poses[0];  // the fixed vertex where the truth has it
  return t;
}

OptimizeSettings with_method(Method m) {
  OptimizeSettings s;
  s.method = m;
  s.iterations = 50;
  return s;
}

void expect_poses_near(std::span<const Pose2> a, std::span<const Pose2> b, double tolerance) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a[i].x, b[i].x, tolerance) << "vertex " << i;
    EXPECT_NEAR(a[i].y, b[i].y, tolerance) << "vertex " << i;
    EXPECT_NEAR(wrap_angle(a[i].theta - b[i].theta), 0.0, tolerance) << "vertex " << i;
  }
}

// One edge, by hand: X_0 = (1, 2, pi/2), X_1 = (1, 5, pi/2) puts vertex 1 at (3, 0, 0) in 0's
// frame; the edge says (2, 0.5, 0.1), so r = (1, -0.5, -0.1).
TEST(GraphScore, MatchesAHandComputation) {
  PoseGraph g;
  g.vertices = {{1, 2, std::numbers::pi / 2}, {1, 5, std::numbers::pi / 2}};
  Eigen::Matrix3d w = Eigen::Matrix3d::Zero();
  w.diagonal() << 2.0, 4.0, 100.0;
  g.edges.push_back({0, 1, {2, 0.5, 0.1}, w});
  const Eigen::Vector3d r = edge_residual(oriented_edges(g)[0], g.vertices[0], g.vertices[1]);
  EXPECT_NEAR(r.x(), 1.0, 1e-15);
  EXPECT_NEAR(r.y(), -0.5, 1e-15);
  EXPECT_NEAR(r.z(), -0.1, 1e-15);
  const Scores s = score(g, g.vertices);
  EXPECT_NEAR(s.chi2, 2.0 + 1.0 + 1.0, 1e-12);  // 2 * 1 + 4 * 0.25 + 100 * 0.01
  EXPECT_NEAR(s.weight, 1.0 - std::exp(-2.0), 1e-15);
  // Stored from vertex 1, the edge is seen from vertex 0 inverted to first order.
  PoseGraph backward = g;
  std::swap(backward.edges[0].from, backward.edges[0].to);
  const OrientedEdge e = oriented_edges(backward)[0];
  EXPECT_EQ(e.lo, 0U);
  EXPECT_EQ(e.hi, 1U);
  const Gaussian2 expected = oriented(backward.edges[0], 0);
  EXPECT_NEAR((e.mean.vector() - expected.mean().vector()).norm(), 0.0, 1e-15);
  EXPECT_NEAR((e.information - expected.information()).norm(), 0.0, 1e-9);
  const Eigen::Vector3d rb = edge_residual(e, g.vertices[0], g.vertices[1]);
  EXPECT_NEAR(score(backward, g.vertices).chi2, rb.dot(e.information * rb), 1e-12);
}

// The analytic gradient against central differences, with fixed vertices inside the graph and
// at several kernel widths; the weight at width 1 is the graph's score.
TEST(GraphObjective, GradientMatchesFiniteDifferences) {
  Truth t = random_graph(9, 4, 3, 0.6);
  t.graph.fixed = {0, 4};
  GraphObjective objective(t.graph);
  EXPECT_EQ(objective.dimension(), 3U * 7U);
  const std::vector<double> x = objective.pack(t.graph.vertices);
  EXPECT_NEAR(objective.evaluate(x).weight, score(t.graph, t.graph.vertices).weight, 1e-12);
  for (const double width : {1.0, 3.0}) {
    objective.set_kernel_width(width);
    std::vector<double> gradient(x.size());
    objective.evaluate(x, gradient);
    for (std::size_t d = 0; d < x.size(); ++d) {
      std::vector<double> plus = x, minus = x;
      const double h = 1e-6;
      plus[d] += h;
      minus[d] -= h;
      const double numeric =
          (objective.evaluate(plus).weight - objective.evaluate(minus).weight) / (2 * h);
      EXPECT_NEAR(gradient[d], numeric, 1e-6 * (1.0 + std::abs(numeric))) << "d = " << d;
    }
  }
  // The fixed vertices keep the graph's poses.
  const std::vector<Pose2> back = objective.unpack(x);
  EXPECT_EQ(back[4].x, t.graph.vertices[4].x);
}

// Exact measurements: least squares from perturbed estimates recovers the poses the edges were
// measured between, with vertex 0 where the file puts it (not at the origin).
TEST(GraphOptimize, CeresRecoversConsistentPosesAndKeepsTheAnchor) {
  const Truth t = random_graph(30, 8, 5, 0.4);
  ASSERT_NE(t.graph.vertices[0].x, 0.0);
  for (const Method m : {Method::ceres, Method::ceres_robust, Method::nlopt}) {
    OptimizeSettings s = with_method(m);
    s.refine.max_evaluations = 20000;
    const OptimizeResult r = optimize(t.graph, "circle.g2o", s, {});
    SCOPED_TRACE(std::string(to_string(m)));
    EXPECT_EQ(r.frames[0].x, t.poses[0].x);  // held, bit for bit
    expect_poses_near(r.frames, t.poses, m == Method::nlopt ? 1e-3 : 1e-7);
    EXPECT_NEAR(r.scores.weight, score(t.graph, r.frames).weight, 1e-15);
    EXPECT_EQ(r.alignments.size(), 29U);
    EXPECT_EQ(r.convergence.size(), 1U);
  }
}

// Noisy measurements: at Ceres' optimum the gradient of chi2 / 2 vanishes (the objective at a
// kernel width far beyond every residual is chi2 / 2 to many digits).
TEST(GraphOptimize, CeresStopsWhereTheLeastSquaresGradientVanishes) {
  Truth t = random_graph(20, 6, 8, 0.2);
  aco::Rng rng(5);
  for (PoseGraphEdge& e : t.graph.edges)
    e.measurement =
        Pose2::from_vector(e.measurement.vector() +
                           0.05 * Eigen::Vector3d(rng.uniform(), rng.uniform(), rng.uniform()));
  const OptimizeResult r = optimize(t.graph, "noisy.g2o", with_method(Method::ceres), {});
  EXPECT_LT(r.scores.chi2, score(t.graph, t.graph.vertices).chi2);
  PoseGraph at_optimum = t.graph;
  at_optimum.vertices = r.frames;
  GraphObjective objective(at_optimum);
  objective.set_kernel_width(1e6);
  const auto largest_gradient = [&](std::span<const Pose2> poses) {
    std::vector<double> gradient(objective.dimension());
    objective.evaluate(objective.pack(poses), gradient);
    double largest = 0.0;
    for (const double g : gradient) largest = std::max(largest, std::abs(g));
    return largest;
  };
  EXPECT_GT(largest_gradient(t.graph.vertices), 0.1);
  EXPECT_LT(largest_gradient(r.frames), 1e-6);
}

// The graph's objective is its fragment chain's (edges in either direction): Ceres on either,
// from the same start, reaches the same poses and scores.
TEST(GraphOptimize, CeresOnTheGraphEqualsCeresOnItsChain) {
  Truth t = random_graph(15, 5, 12, 0.3);
  aco::Rng rng(2);
  for (PoseGraphEdge& e : t.graph.edges)  // noise, so that the optimum is not the truth
    e.measurement =
        Pose2::from_vector(e.measurement.vector() +
                           0.1 * Eigen::Vector3d(rng.uniform(), rng.uniform(), rng.uniform()));
  t.graph.vertices[0] = Pose2{};
  const FragmentSet set = fragment_set_from_g2o(t.graph, {.samples = 3}, "chain");
  OptimizeSettings s = with_method(Method::ceres);
  s.initial = relative_alignments(t.graph.vertices);
  const OptimizeResult on_set = optimize(set, s);
  const OptimizeResult on_graph = optimize(t.graph, "chain", with_method(Method::ceres), {});
  expect_poses_near(on_graph.frames, on_set.frames, 1e-8);
  EXPECT_NEAR(on_graph.scores.chi2, on_set.scores.chi2, 1e-9);
  EXPECT_NEAR(on_graph.scores.weight, on_set.scores.weight, 1e-9);
}

// Two sessions with no odometry between them: least squares and NLopt run (the closures tie
// them), the ants cannot and say why.
TEST(GraphOptimize, SessionsWithoutAChainRunByLeastSquaresOnly) {
  const Truth t = random_graph(16, 6, 21, 0.3, /*sessions=*/true);
  for (const Method m : {Method::ceres, Method::nlopt}) {
    OptimizeSettings s = with_method(m);
    s.refine.max_evaluations = 20000;
    const OptimizeResult r = optimize(t.graph, "sessions.g2o", s, {});
    expect_poses_near(r.frames, t.poses, m == Method::nlopt ? 1e-3 : 1e-7);
  }
  EXPECT_EQ(testing::error_of([&] {
              try {
                optimize(t.graph, "sessions.g2o", with_method(Method::hybrid), {});
              } catch (const std::invalid_argument& e) {
                throw std::runtime_error(e.what());
              }
            }),
            "sessions.g2o: no edge between vertices 7 and 8: the ant methods need one between "
            "every two consecutive vertices (their samples are poses of vertex i in the frame of "
            "vertex i-1); ceres, ceres-robust and nlopt run on any connected graph");
}

std::string invalid_argument_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

// FIX: every fixed vertex is held by least squares; a graph in two parts needs one in each.
TEST(GraphOptimize, HoldsEveryFixedVertexAndNeedsOneInEachPart) {
  Truth t = random_graph(16, 0, 4, 0.3, /*sessions=*/true);  // two parts, nothing between
  EXPECT_EQ(
      invalid_argument_of([&] { optimize(t.graph, "two.g2o", with_method(Method::ceres), {}); }),
      "two.g2o: vertex 8 is joined to no fixed vertex by edges, so its pose is undetermined "
      "(connect the graph, or FIX a vertex of each part)");
  t.graph.fixed = {0, 11};
  t.graph.vertices[11] = t.poses[11];
  const OptimizeResult r = optimize(t.graph, "two.g2o", with_method(Method::ceres), {});
  EXPECT_EQ(r.frames[11].y, t.poses[11].y);
  expect_poses_near(r.frames, t.poses, 1e-7);
  EXPECT_EQ(
      invalid_argument_of([&] { optimize(t.graph, "two.g2o", with_method(Method::mmas), {}); }),
      "two.g2o: the graph fixes 2 vertices (FIX lines); the methods on its fragment chain "
      "hold one, ceres, ceres-robust and nlopt hold them all");
  OptimizeSettings with_initial = with_method(Method::ceres);
  with_initial.initial.resize(15);
  EXPECT_EQ(invalid_argument_of([&] { optimize(t.graph, "two.g2o", with_initial, {}); }),
            "optimize: a pose graph starts from its vertex poses; set those instead of `initial`");
}

// Every vertex fixed: nothing to optimize, and every continuous method returns the file's poses
// (NLopt, given no unknowns, failed with "NULL args to nlopt_optimize_").
TEST(GraphOptimize, AGraphWithEveryVertexFixedKeepsItsPoses) {
  Truth t = random_graph(6, 2, 5, 0.3);
  t.graph.fixed = {0, 1, 2, 3, 4, 5};
  for (const Method m : {Method::nlopt, Method::ceres, Method::ceres_robust}) {
    const OptimizeResult r = optimize(t.graph, "fixed.g2o", with_method(m), {});
    ASSERT_EQ(r.frames.size(), t.graph.vertices.size()) << to_string(m);
    for (std::size_t v = 0; v < r.frames.size(); ++v) {
      EXPECT_EQ(r.frames[v].x, t.graph.vertices[v].x) << to_string(m) << " vertex " << v;
      EXPECT_EQ(r.frames[v].y, t.graph.vertices[v].y) << to_string(m) << " vertex " << v;
      EXPECT_EQ(r.frames[v].theta, t.graph.vertices[v].theta) << to_string(m) << " vertex " << v;
    }
  }
}

// The ants on a graph's chain: their frames move rigidly onto the fixed vertex's pose, and the
// result is scored over the graph's edges.
TEST(GraphOptimize, AntsKeepTheFixedVertexWhereTheFilePutsIt) {
  Truth t = random_graph(8, 3, 30, 0.2);
  t.graph.fixed = {3};
  t.graph.vertices[3] = {7.0, -2.0, 0.4};
  const OptimizeResult r = optimize(t.graph, "g.g2o", with_method(Method::hybrid), {.samples = 5});
  EXPECT_NEAR(r.frames[3].x, 7.0, 1e-12);
  EXPECT_NEAR(r.frames[3].y, -2.0, 1e-12);
  EXPECT_NEAR(r.frames[3].theta, 0.4, 1e-12);
  EXPECT_EQ(r.choice.size(), 7U);
  EXPECT_NEAR(r.scores.weight, score(t.graph, r.frames).weight, 1e-15);
  // The same trials through run_trials, on any thread count.
  const auto one = run_trials(t.graph, "g.g2o", with_method(Method::hybrid), {.samples = 5},
                              {.trials = 3, .threads = 1});
  const auto two = run_trials(t.graph, "g.g2o", with_method(Method::hybrid), {.samples = 5},
                              {.trials = 3, .threads = 2});
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(one[k].choice, two[k].choice);
    EXPECT_EQ(one[k].scores.weight, two[k].scores.weight);
    EXPECT_NEAR(one[k].frames[3].x, 7.0, 1e-12);
  }
}

// The bundled benchmark graph: least squares from the file's vertices lowers chi2, the first
// vertex stays where the file has it.
TEST(GraphOptimize, CeresOnTheRingGraph) {
  const PoseGraph ring = read_g2o_file(ANTSLAM_DATA_DIR "/posegraphs/ring.g2o");
  const OptimizeResult r = optimize(ring, "ring.g2o", with_method(Method::ceres), {});
  EXPECT_LT(r.scores.chi2, 0.5 * score(ring, ring.vertices).chi2);
  EXPECT_EQ(r.frames[0].x, ring.vertices[0].x);
  EXPECT_EQ(r.frames.size(), 434U);
}

}  // namespace
}  // namespace antslam::slam
