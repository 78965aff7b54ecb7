// Pairwise consistency of loop closures: the chi-square quantile, the chain split, hand-computed
// cycles on a straight chain, and the O(1) prefix-sum test against the cycle composed step by
// step with its covariance from a numerical Jacobian, on graphs with correlated covariances.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "antslam/aco/backend_kind.hpp"
#include "antslam/slamgraph/chain.hpp"
#include "antslam/slamgraph/chi_square.hpp"
#include "antslam/slamgraph/consistency.hpp"
#include "pose_graphs.hpp"
#include "support.hpp"

namespace antslam::slam {
namespace {

TEST(ChiSquare3, KnownQuantiles) {
  EXPECT_NEAR(chi_square3_quantile(0.95), 7.814727903, 1e-8);
  EXPECT_NEAR(chi_square3_quantile(0.99), 11.344866730, 1e-8);
  EXPECT_NEAR(chi_square3_cdf(chi_square3_quantile(0.5)), 0.5, 1e-12);
  EXPECT_EQ(chi_square3_cdf(-1.0), 0.0);
  EXPECT_THROW(chi_square3_quantile(1.0), std::invalid_argument);
  EXPECT_THROW(chi_square3_quantile(0.0), std::invalid_argument);
}

PoseGraphEdge edge(std::size_t i, std::size_t j, Pose2 z, const Eigen::Matrix3d& covariance) {
  return {i, j, z, covariance.inverse()};
}

TEST(Chain, SplitsOdometryFromClosuresInEitherDirection) {
  PoseGraph g;
  g.vertices.resize(4);
  const Eigen::Matrix3d c = Eigen::Matrix3d::Identity();
  g.edges = {edge(0, 1, {1, 0, 0}, c), edge(2, 1, {-1, 0, 0}, c), edge(0, 2, {2, 0, 0}, c),
             edge(1, 2, {1, 0, 0}, c), edge(2, 3, {1, 0, 0}, c),  edge(3, 0, {-3, 0, 0}, c)};
  const ChainSplit split = split_chain(g, "g");
  EXPECT_EQ(split.chain, (std::vector<std::size_t>{0, 1, 4}));  // edge 3 is odometry too
  EXPECT_EQ(split.closures, (std::vector<std::size_t>{2, 5}));
  const std::vector<Pose2> poses = chain_poses(g, split);
  EXPECT_NEAR(poses[3].x, 3.0, 1e-12);
  g.edges.erase(g.edges.begin() + 4);
  EXPECT_EQ(testing::error_of([&] { split_chain(g, "g.g2o"); }),
            "g.g2o: no edge between vertices 2 and 3 (the graph must chain consecutive poses)");
}

TEST(Chain, SplitsAMultiSessionGraphIntoItsSessions) {
  PoseGraph g;  // sessions 0-2 and 3-5; vertex 3's estimate places the second one
  g.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 5, 1.0}, {9, 9, 9}, {9, 9, 9}};
  const Eigen::Matrix3d c = Eigen::Matrix3d::Identity();
  g.edges = {edge(0, 1, {1, 0, 0}, c),  edge(1, 2, {1, 0, 0}, c), edge(3, 4, {1, 0, 0}, c),
             edge(5, 4, {-1, 0, 0}, c), edge(2, 4, {0, 1, 0}, c), edge(0, 2, {2, 0, 0}, c)};
  EXPECT_EQ(testing::error_of([&] { split_chain(g, "g.g2o"); }),
            "g.g2o: no edge between vertices 2 and 3 (the graph must chain consecutive poses)");
  const ChainSplit s = split_sessions(g, "g.g2o");
  EXPECT_EQ(s.first, (std::vector<std::size_t>{0, 3}));
  EXPECT_EQ(s.chain, (std::vector<std::size_t>{0, 1, kNoStep, 2, 3}));
  EXPECT_EQ(s.closures, (std::vector<std::size_t>{4, 5}));  // between and within sessions
  const std::size_t sessions[] = {0, 0, 0, 1, 1, 1};
  for (std::size_t v = 0; v < 6; ++v) EXPECT_EQ(s.session_of(v), sessions[v]) << v;
  const std::vector<Pose2> poses = chain_poses(g, s);
  EXPECT_NEAR(poses[2].x, 2.0, 1e-12);
  EXPECT_NEAR(poses[3].x, 5.0, 1e-12);                        // the file's estimate
  EXPECT_NEAR(poses[5].x, 5.0 + 2.0 * std::cos(1.0), 1e-12);  // then the session's odometry
  EXPECT_NEAR(poses[5].y, 5.0 + 2.0 * std::sin(1.0), 1e-12);
  g.vertices.push_back({0, 0, 0});  // vertex 6: no odometry reaches it
  EXPECT_EQ(testing::error_of([&] { split_sessions(g, "g.g2o"); }),
            "g.g2o: vertex 6 has no edge to the vertex before or after it (a session of one "
            "pose)");
}

/// A straight chain of unit steps along x with isotropic translation variance sigma2 and a
/// negligible heading variance, so that cycle covariances are sums of translation variances.
PoseGraph straight_chain(std::size_t n, double sigma2) {
  PoseGraph g;
  for (std::size_t i = 0; i < n; ++i) g.vertices.push_back({static_cast<double>(i), 0.0, 0.0});
  const Eigen::Matrix3d c = Eigen::Vector3d(sigma2, sigma2, 1e-14).asDiagonal();
  for (std::size_t i = 0; i + 1 < n; ++i) g.edges.push_back(edge(i, i + 1, {1, 0, 0}, c));
  return g;
}

TEST(Consistency, HandComputedCyclesOnAStraightChain) {
  const double s2 = 0.01, c2 = 0.04, delta = 0.3;
  PoseGraph g = straight_chain(10, s2);
  const Eigen::Matrix3d c = Eigen::Vector3d(c2, c2, 1e-14).asDiagonal();
  g.edges.push_back(edge(0, 3, {3.0 + delta, 0, 0}, c));  // overlapping spans: 0-3 and 1-4
  g.edges.push_back(edge(4, 1, {-3.0, 0, 0}, c));         // stored backwards
  g.edges.push_back(edge(5, 7, {2.0, delta, 0}, c));      // disjoint from 0-3
  g.edges.push_back(edge(0, 9, {9.0, 0, 0}, c));          // holds 5-7 inside
  const CycleTest test(g, split_chain(g, "g"));
  // Steps 0 and 3 lie in one span only: 2 s2 + 2 c2 in x.
  EXPECT_NEAR(test.squared_distance(0, 1), delta * delta / (2 * s2 + 2 * c2), 1e-9);
  // Disjoint: steps 0, 1, 2 and 5, 6; the error is delta in x and delta in y.
  EXPECT_NEAR(test.squared_distance(0, 2), 2 * delta * delta / (5 * s2 + 2 * c2), 1e-9);
  // Nested: 9 - 2 = 7 steps; the cycle is (-delta... ) in y only.
  EXPECT_NEAR(test.squared_distance(2, 3), delta * delta / (7 * s2 + 2 * c2), 1e-9);
  EXPECT_NEAR(test.squared_distance(3, 2), test.squared_distance(2, 3), 1e-12);
  // Against the odometry between its own ends: 3 steps and the closure.
  EXPECT_NEAR(test.squared_distance(0), delta * delta / (3 * s2 + c2), 1e-9);
  EXPECT_NEAR(test.squared_distance(3), 0.0, 1e-12);
}

/// Log of an SE(2) element: (V(theta)^-1 t, theta), V = [sin t / t, -(1 - cos t) / t; ...].
Eigen::Vector3d se2_log(const Pose2& p) {
  const double t = p.theta;
  Eigen::Matrix2d v = Eigen::Matrix2d::Identity();
  if (std::abs(t) > 1e-9)
    v << std::sin(t) / t, -(1 - std::cos(t)) / t, (1 - std::cos(t)) / t, std::sin(t) / t;
  const Eigen::Vector2d rho = v.inverse() * p.translation();
  return {rho.x(), rho.y(), t};
}

/// A cycle composed from the measurements it uses, in order (each oriented from `from`, or
/// inverted), its residual Log(C) and the covariance of its left perturbation from the numerical
/// Jacobian with respect to every measurement (right perturbations z * d; a step the cycle passes
/// twice, once each way, is one measurement); returns the squared Mahalanobis distance.
struct Use {
  std::size_t edge;  // index into g.edges
  std::size_t from;  // the vertex the measurement is oriented from
  bool inverse;
};
double brute_force_distance(const PoseGraph& g, const std::vector<Use>& uses) {
  std::vector<std::size_t> edges;  // the distinct measurements, one perturbation each
  std::vector<Eigen::Index> slot;  // of each use
  std::vector<Pose2> mean;         // of each use
  for (const Use& u : uses) {
    auto it = std::find(edges.begin(), edges.end(), u.edge);
    if (it == edges.end()) it = edges.insert(edges.end(), u.edge);
    slot.push_back(3 * static_cast<Eigen::Index>(it - edges.begin()));
    mean.push_back(oriented(g.edges[u.edge], u.from).mean());
  }
  const auto cycle = [&](const Eigen::VectorXd& d) {
    Pose2 p;
    for (std::size_t u = 0; u < uses.size(); ++u) {
      const Pose2 z = mean[u] * Pose2::from_vector(d.segment<3>(slot[u]));
      p = p * (uses[u].inverse ? z.inverse() : z);
    }
    return p;
  };
  const auto dims = static_cast<Eigen::Index>(3 * edges.size());
  const Pose2 at = cycle(Eigen::VectorXd::Zero(dims));
  Eigen::MatrixXd jacobian(3, dims), covariance = Eigen::MatrixXd::Zero(dims, dims);
  for (Eigen::Index i = 0; i < dims; ++i) {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(dims);
    d[i] = 1e-6;
    const Eigen::Vector3d plus = se2_log(cycle(d) * at.inverse());
    d[i] = -1e-6;
    jacobian.col(i) = (plus - se2_log(cycle(d) * at.inverse())) / 2e-6;
  }
  for (std::size_t u = 0; u < uses.size(); ++u)
    covariance.block<3, 3>(slot[u], slot[u]) =
        oriented(g.edges[uses[u].edge], uses[u].from).covariance();
  const Eigen::Matrix3d cycle_covariance = jacobian * covariance * jacobian.transpose();
  const Eigen::Vector3d e = se2_log(at);
  return e.dot(cycle_covariance.ldlt().solve(e));
}

/// The uses of the odometry from vertex `from` to vertex `to` along the chain.
void add_odometry(const ChainSplit& split, std::size_t from, std::size_t to,
                  std::vector<Use>& uses) {
  if (from < to)
    for (std::size_t s = from; s < to; ++s) uses.push_back({split.chain[s], s, false});
  for (std::size_t s = from; s-- > to;) uses.push_back({split.chain[s], s, true});
}

std::pair<std::size_t, std::size_t> span_of(const PoseGraph& g, const ChainSplit& split,
                                            std::size_t c) {
  const PoseGraphEdge& e = g.edges[split.closures[c]];
  return {std::min(e.from, e.to), std::max(e.from, e.to)};
}

/// The cycle a1 -z1-> b1 -odometry-> b2 -z2^-1-> a2 -odometry-> a1.
double brute_force_cycle(const PoseGraph& g, const ChainSplit& split, std::size_t k,
                         std::size_t l) {
  const auto [a1, b1] = span_of(g, split, k);
  const auto [a2, b2] = span_of(g, split, l);
  std::vector<Use> uses{{split.closures[k], a1, false}};
  add_odometry(split, b1, b2, uses);
  uses.push_back({split.closures[l], a2, true});
  add_odometry(split, a2, a1, uses);
  return brute_force_distance(g, uses);
}

/// The cycle a -z-> b -odometry-> a.
double brute_force_cycle(const PoseGraph& g, const ChainSplit& split, std::size_t k) {
  const auto [a, b] = span_of(g, split, k);
  std::vector<Use> uses{{split.closures[k], a, false}};
  add_odometry(split, b, a, uses);
  return brute_force_distance(g, uses);
}

/// The Mahalanobis distance of a cycle from its residual and covariance (no heading-only rule).
double mahalanobis(const Cycle& c) { return c.residual.dot(c.covariance.ldlt().solve(c.residual)); }

TEST(Consistency, MatchesTheCycleComposedStepByStep) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const testing::TrueGraph t = testing::square_laps(3, 6, 4, 0.002, seed);
    const ChainSplit split = split_chain(t.graph, "square");
    const CycleTest test(t.graph, split);
    ASSERT_GE(test.closures(), 8U);
    for (std::size_t k = 0; k < test.closures(); ++k)
      for (std::size_t l = k + 1; l < test.closures(); ++l) {
        const double expected = brute_force_cycle(t.graph, split, k, l);
        EXPECT_NEAR(test.squared_distance(k, l), expected, 0.005 * expected + 1e-9)
            << "closures " << k << " and " << l << ", seed " << seed;
      }
  }
}

TEST(Consistency, MatchesTheCycleComposedStepByStepWhereTheOdometryDrifted) {
  // Every odometry step turns 0.08 rad more than it did: after a lap the chain is off by
  // radians, the corrections Y are far from the identity, and a covariance propagated as if they
  // were not (or a residual in x, y, theta of the cycle instead of Log) is wrong to first order.
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    testing::TrueGraph t = testing::square_laps(3, 6, 3, 0.002, seed);
    for (PoseGraphEdge& e : t.graph.edges)
      if (is_odometry(e)) e.measurement = e.measurement * Pose2{0.0, 0.0, 0.08};
    const ChainSplit split = split_chain(t.graph, "square");
    const CycleTest test(t.graph, split);
    ASSERT_GE(test.closures(), 10U);
    for (std::size_t k = 0; k < test.closures(); ++k) {
      const double unary = brute_force_cycle(t.graph, split, k);
      EXPECT_NEAR(mahalanobis(test.cycle(k)), unary, 1e-4 * unary) << "closure " << k;
      for (std::size_t l = 0; l < test.closures(); ++l) {
        if (l == k) continue;
        // Based at the closure with the lower first vertex, as CycleTest anchors it: based
        // elsewhere the cycle is conjugated by odometry it also contains, which changes its
        // first-order covariance by terms that vanish only where the cycle is the identity.
        const bool k_first = span_of(t.graph, split, k).first <= span_of(t.graph, split, l).first;
        const double expected = k_first ? brute_force_cycle(t.graph, split, k, l)
                                        : brute_force_cycle(t.graph, split, l, k);
        EXPECT_NEAR(mahalanobis(test.cycle(k, l)), expected, 1e-4 * expected)
            << "closures " << k << " and " << l << ", seed " << seed;
      }
    }
  }
}

TEST(Consistency, BetweenSessionsMatchesTheCycleComposedStepByStep) {
  // The drifted laps cut in two (the odometry edge after vertex 20 removed): closures across the
  // cut join the sessions; two of them close a cycle through both sessions' odometry, a pair of
  // other kinds none.
  for (std::uint64_t seed = 1; seed <= 2; ++seed) {
    testing::TrueGraph t = testing::square_laps(3, 6, 3, 0.002, seed);
    for (PoseGraphEdge& e : t.graph.edges)
      if (is_odometry(e)) e.measurement = e.measurement * Pose2{0.0, 0.0, 0.08};
    std::erase_if(t.graph.edges, [](const PoseGraphEdge& e) {
      return std::min(e.from, e.to) == 20 && std::max(e.from, e.to) == 21;
    });
    const ChainSplit split = split_sessions(t.graph, "cut");
    ASSERT_EQ(split.first, (std::vector<std::size_t>{0, 21}));
    const CycleTest test(t.graph, split);
    std::size_t between = 0, within = 0, none = 0;
    for (std::size_t k = 0; k < test.closures(); ++k)
      for (std::size_t l = 0; l < test.closures(); ++l) {
        if (l == k) continue;
        const auto [k_lo, k_hi] = span_of(t.graph, split, k);
        const auto [l_lo, l_hi] = span_of(t.graph, split, l);
        const bool k_across = k_lo <= 20 && k_hi >= 21, l_across = l_lo <= 20 && l_hi >= 21;
        const bool same_session = !k_across && !l_across && (k_hi <= 20) == (l_hi <= 20);
        if (!(k_across && l_across) && !same_session) {
          EXPECT_FALSE(test.closes_cycle(k, l));
          EXPECT_EQ(test.squared_distance(k, l), 0.0);
          EXPECT_THROW(test.cycle(k, l), std::invalid_argument);
          ++none;
          continue;
        }
        ASSERT_TRUE(test.closes_cycle(k, l)) << k << " " << l;
        ++(k_across ? between : within);
        const double expected = k_lo <= l_lo ? brute_force_cycle(t.graph, split, k, l)
                                             : brute_force_cycle(t.graph, split, l, k);
        EXPECT_NEAR(mahalanobis(test.cycle(k, l)), expected, 1e-4 * expected)
            << "closures " << k << " and " << l << ", seed " << seed;
      }
    EXPECT_GE(between, 6U);
    EXPECT_GE(within, 6U);
    EXPECT_GE(none, 6U);
    const ConsistencyGraph graph = pairwise_consistency(t.graph, split);
    std::set<std::pair<std::uint32_t, std::uint32_t>> pairs(graph.pairs.begin(), graph.pairs.end());
    for (std::uint32_t k = 0; k < test.closures(); ++k)
      for (std::uint32_t l = k + 1; l < test.closures(); ++l)
        EXPECT_EQ(pairs.contains({k, l}), graph.odometry_consistent[k] &&
                                              graph.odometry_consistent[l] &&
                                              test.squared_distance(k, l) <= graph.threshold)
            << k << " " << l;
    for (std::size_t k = 0; k < test.closures(); ++k) {
      const auto [lo, hi] = span_of(t.graph, split, k);
      EXPECT_EQ(test.closes_cycle(k), !(lo <= 20 && hi >= 21));
      if (!test.closes_cycle(k)) {
        EXPECT_EQ(test.squared_distance(k), 0.0);
      }
    }
  }
}

TEST(Consistency, BeyondTheLinearRegimeOnlyTheHeadingIsTested) {
  // A straight chain whose steps show a heading deviation of 0.3 rad: with the linear regime at
  // kLinearHeadingSd, a closure over 2 steps (heading sd 0.3 sqrt(2) = 0.42 rad) is tested in x,
  // y, theta; one over 9 steps (sd 0.9 rad) by its heading alone, at the 3-dof threshold scaled
  // from the 1-dof one.
  PoseGraph g;
  for (std::size_t i = 0; i < 12; ++i) g.vertices.push_back({static_cast<double>(i), 0.0, 0.0});
  const Eigen::Matrix3d step = Eigen::Vector3d(0.01, 0.01, 0.09).asDiagonal();
  for (std::size_t i = 0; i + 1 < 12; ++i) g.edges.push_back({i, i + 1, {1, 0, 0}, step.inverse()});
  const Eigen::Matrix3d closure = Eigen::Vector3d(0.01, 0.01, 1e-6).asDiagonal();
  g.edges.push_back({0, 2, {2.0, 0.0, 0.2}, closure.inverse()});
  g.edges.push_back({1, 10, {9.0, 0.0, 0.2}, closure.inverse()});
  const CycleTest test(g, split_chain(g, "g"), {.linear_heading_sd = kLinearHeadingSd});
  const Cycle near = test.cycle(0), far = test.cycle(1);
  ASSERT_LT(near.covariance(2, 2), kLinearHeadingSd * kLinearHeadingSd);
  ASSERT_GT(far.covariance(2, 2), kLinearHeadingSd * kLinearHeadingSd);
  EXPECT_NEAR(test.squared_distance(0), mahalanobis(near), 1e-9);
  EXPECT_NEAR(far.residual.z(), 0.2, 1e-12);
  EXPECT_NEAR(far.covariance(2, 2), 9 * 0.09 + 1e-6, 1e-12);
  const double factor = chi_square3_quantile(0.99) / chi_square1_quantile(0.99);
  EXPECT_NEAR(test.squared_distance(1), 0.04 / (9 * 0.09 + 1e-6) * factor, 1e-9);
  // By default (the covariances as stated: their regime unknown) every cycle in x, y, theta.
  const CycleTest stated(g, split_chain(g, "g"));
  EXPECT_NEAR(stated.squared_distance(1), mahalanobis(far), 1e-9);
  EXPECT_NEAR(chi_square1_quantile(0.99), 6.634896601, 1e-6);  // 2.5758^2
  EXPECT_NEAR(chi_square1_cdf(3.841458821), 0.95, 1e-9);
}

TEST(Consistency, GraphHoldsExactlyThePairsBelowTheThresholdOnEveryBackend) {
  testing::TrueGraph t = testing::square_laps(4, 5, 2, 0.02, 9);
  aco::Rng rng(5);
  for (int f = 0; f < 6; ++f)  // false closures: random vertices, measurement near identity
    t.graph.edges.push_back({rng.below(40), 40 + rng.below(40), Pose2{0.1, -0.1, 0.05},
                             100.0 * Eigen::Matrix3d::Identity()});
  t.graph.edges.push_back({3, 6, Pose2{}, 100.0 * Eigen::Matrix3d::Identity()});  // fails alone
  const ChainSplit split = split_chain(t.graph, "square");
  const CycleTest test(t.graph, split);
  const double threshold = chi_square3_quantile(0.99);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> expected;
  std::vector<bool> unary;
  for (std::uint32_t k = 0; k < test.closures(); ++k)
    unary.push_back(test.squared_distance(k) <= threshold);
  for (std::uint32_t k = 0; k < test.closures(); ++k)
    for (std::uint32_t l = k + 1; l < test.closures(); ++l)
      if (unary[k] && unary[l] && test.squared_distance(k, l) <= threshold)
        expected.emplace_back(k, l);
  ASSERT_GT(expected.size(), 10U);
  ASSERT_LT(expected.size(), test.closures() * (test.closures() - 1) / 2);  // some fail
  ASSERT_FALSE(unary.back());
  using aco::BackendKind;
  for (const auto& [backend, threads] : {std::pair{BackendKind::serial, std::size_t{1}},
                                         {BackendKind::tbb, 2},
                                         {BackendKind::omp, 3}}) {
    const ConsistencyGraph graph = pairwise_consistency(
        t.graph, split, {.confidence = 0.99, .backend = backend, .threads = threads});
    EXPECT_EQ(graph.closures, test.closures());
    EXPECT_EQ(graph.threshold, threshold);
    EXPECT_EQ(graph.pairs, expected);
    EXPECT_EQ(graph.odometry_consistent, unary);
  }
  EXPECT_THROW(pairwise_consistency(t.graph, split, {.confidence = 1.5}), std::invalid_argument);
}

TEST(Consistency, AFragmentSetGivesTheSameGraphAsItsPoseGraph) {
  testing::TrueGraph t = testing::square_laps(4, 5, 2, 0.05, 4);
  aco::Rng rng(8);
  for (int f = 0; f < 6; ++f)
    t.graph.edges.push_back({rng.below(40), 40 + rng.below(40), Pose2{0.1, -0.1, 0.05},
                             100.0 * Eigen::Matrix3d::Identity()});
  const FragmentSet set = fragment_set_from_g2o(t.graph, {.samples = 1}, "square");
  const ConsistencyGraph from_set = pairwise_consistency(set);
  const ConsistencyGraph from_graph = pairwise_consistency(t.graph, split_chain(t.graph, "square"));
  EXPECT_EQ(from_set.closures, set.closures.size());
  EXPECT_EQ(from_set.pairs, from_graph.pairs);
  EXPECT_EQ(from_set.odometry_consistent, from_graph.odometry_consistent);
  EXPECT_LT(from_set.pairs.size(), from_set.closures * (from_set.closures - 1) / 2);
}

TEST(Consistency, NoiseFreeClosuresAreAllConsistent) {
  const testing::TrueGraph t = testing::square_laps(3, 5, 1, 0.0, 1);
  const ChainSplit split = split_chain(t.graph, "square");
  const ConsistencyGraph graph = pairwise_consistency(t.graph, split);
  const std::size_t m = split.closures.size();
  EXPECT_EQ(graph.pairs.size(), m * (m - 1) / 2);
}

TEST(Consistency, AConfidenceOutsideZeroOneIsRefusedByName) {
  const testing::TrueGraph t = testing::square_laps(3, 5, 1, 0.0, 1);
  const ChainSplit split = split_chain(t.graph, "square");
  for (const double confidence : {0.0, 1.0, 1.5, -0.1, std::nan("")}) {
    try {
      pairwise_consistency(t.graph, split, {.confidence = confidence});
      ADD_FAILURE() << "confidence " << confidence << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(
          std::string(e.what()).rfind("pairwise consistency: confidence must be in (0, 1)", 0), 0U)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace antslam::slam
