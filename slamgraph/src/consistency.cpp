#include "antslam/slamgraph/consistency.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "antslam/aco/backend_factory.hpp"
#include "antslam/slamgraph/chi_square.hpp"

namespace antslam::slam {

namespace {

Eigen::Matrix3d adjoint(double x, double y, double c, double s) {
  Eigen::Matrix3d ad;
  ad << c, -s, y, s, c, -x, 0.0, 0.0, 1.0;
  return ad;
}

Eigen::Matrix3d adjoint(const Pose2& t) {
  return adjoint(t.x, t.y, std::cos(t.theta), std::sin(t.theta));
}

/// Log of the SE(2) element (x, y, angle theta with cosine c and sine s): (V(theta)^-1 t, theta).
Eigen::Vector3d se2_log(double x, double y, double theta, double c, double s) {
  double a = 1.0 - theta * theta / 6.0, b = 0.5 * theta;  // sin(t)/t, (1 - cos(t))/t near 0
  if (std::abs(theta) > 1e-4) {
    a = s / theta;
    b = (1.0 - c) / theta;
  }
  const double n = a * a + b * b;
  return {(a * x + b * y) / n, (-b * x + a * y) / n, theta};
}

/// e^T C^-1 e for the symmetric C by LDL^T; +infinity unless C is positive definite.
double mahalanobis_squared(const Eigen::Vector3d& e, const Eigen::Matrix3d& c) {
  const double d1 = c(0, 0);
  if (!(d1 > 0.0)) return std::numeric_limits<double>::infinity();
  const double l21 = c(1, 0) / d1, l31 = c(2, 0) / d1;
  const double d2 = c(1, 1) - l21 * c(1, 0);
  if (!(d2 > 0.0)) return std::numeric_limits<double>::infinity();
  const double l32 = (c(2, 1) - l31 * c(1, 0)) / d2;
  const double d3 = c(2, 2) - l31 * c(2, 0) - l32 * l32 * d2;
  if (!(d3 > 0.0)) return std::numeric_limits<double>::infinity();
  const double y1 = e[0], y2 = e[1] - l21 * y1, y3 = e[2] - l31 * y1 - l32 * y2;
  return y1 * y1 / d1 + y2 * y2 / d2 + y3 * y3 / d3;
}

}  // namespace

CycleTest::CycleTest(const PoseGraph& graph, const ChainSplit& split,
                     const ConsistencySettings& settings) {
  const double confidence = settings.confidence;
  if (!(confidence > 0.0 && confidence < 1.0))
    throw std::invalid_argument("pairwise consistency: confidence must be in (0, 1), got " +
                                std::to_string(confidence));
  if (!(settings.linear_heading_sd > 0.0))
    throw std::invalid_argument(
        "pairwise consistency: the linear heading deviation must be "
        "positive, got " +
        std::to_string(settings.linear_heading_sd));
  linear_heading_variance_ = settings.linear_heading_sd * settings.linear_heading_sd;
  heading_only_factor_ = chi_square3_quantile(confidence) / chi_square1_quantile(confidence);
  std::vector<Pose2> pose = chain_poses(graph, split);
  double cx = 0.0, cy = 0.0;
  for (const Pose2& p : pose) {
    cx += p.x;
    cy += p.y;
  }
  cx /= static_cast<double>(pose.size());
  cy /= static_cast<double>(pose.size());
  for (Pose2& p : pose) {
    p.x -= cx;
    p.y -= cy;
  }
  prefix_.assign(pose.size(), Eigen::Matrix3d::Zero());
  for (std::size_t k = 0; k < split.chain.size(); ++k) {
    prefix_[k + 1] = prefix_[k];
    if (split.chain[k] == kNoStep) continue;  // the end of a session
    const Eigen::Matrix3d ad = adjoint(pose[k + 1]);
    const Eigen::Matrix3d sigma = oriented(graph.edges[split.chain[k]], k).covariance();
    prefix_[k + 1] += ad * sigma * ad.transpose();
  }
  for (const std::size_t e : split.closures) {
    const PoseGraphEdge& edge = graph.edges[e];
    Closure c;
    c.lo = std::min(edge.from, edge.to);
    c.hi = std::max(edge.from, edge.to);
    c.from_session = split.session_of(c.lo);
    c.to_session = split.session_of(c.hi);
    const Gaussian2 z = oriented(edge, c.lo);
    const Pose2 y = pose[c.lo] * z.mean() * pose[c.hi].inverse();
    c.x = y.x;
    c.y = y.y;
    c.theta = y.theta;
    c.c = std::cos(y.theta);
    c.s = std::sin(y.theta);
    const Eigen::Matrix3d ad = adjoint(pose[c.hi]);
    c.h = ad * z.covariance() * ad.transpose();
    closure_.push_back(c);
  }
}

bool CycleTest::closes_cycle(std::size_t k, std::size_t l) const {
  const Closure& a = closure_[k];
  const Closure& b = closure_[l];
  return a.from_session == b.from_session && a.to_session == b.to_session;
}

bool CycleTest::closes_cycle(std::size_t k) const {
  return closure_[k].from_session == closure_[k].to_session;
}

Cycle CycleTest::cycle(std::size_t k, std::size_t l) const {
  if (!closes_cycle(k, l))
    throw std::invalid_argument("cycle: closures " + std::to_string(k) + " and " +
                                std::to_string(l) + " close no cycle (other sessions)");
  const Closure* a = &closure_[k];
  const Closure* b = &closure_[l];
  if (b->lo < a->lo) std::swap(a, b);  // the same distance either way (Log(C^-1) = -Log(C))
  // C = Y_A Y_B^-1: angle theta_A - theta_B, translation t_A - R(C) t_B.
  const double c = a->c * b->c + a->s * b->s, s = a->s * b->c - a->c * b->s;
  const double x = a->x - (c * b->x - s * b->y), y = a->y - (s * b->x + c * b->y);
  const double theta = wrap_angle(a->theta - b->theta);
  const auto range = [&](std::size_t from, std::size_t to) -> Eigen::Matrix3d {
    if (from >= to) return Eigen::Matrix3d::Zero();
    return prefix_[to] - prefix_[from];
  };
  const Eigen::Matrix3d ad_c = adjoint(x, y, c, s);
  const Eigen::Matrix3d ad_a = adjoint(a->x, a->y, a->c, a->s);
  Cycle result;
  result.residual = se2_log(x, y, theta, c, s);
  if (a->from_session != a->to_session) {
    // Two closures between sessions P and Q: Y estimates the transform between the sessions'
    // frames; with P anchored at lo_A, P's steps lo_A..lo_B-1 reach C by Ad(C), Q's steps
    // between the two hi ends (either order) by Ad(Y_A), and the closures by Ad(Y_A).
    const std::size_t q_from = std::min(a->hi, b->hi), q_to = std::max(a->hi, b->hi);
    result.covariance = ad_c * range(a->lo, b->lo) * ad_c.transpose() +
                        ad_a * (range(q_from, q_to) + a->h + b->h) * ad_a.transpose();
    return result;
  }
  const Eigen::Matrix3d between = ad_a - ad_c;
  const std::size_t high_from = std::max(b->lo, std::min(a->hi, b->hi));
  result.covariance =
      ad_c * range(a->lo, std::min(b->lo, a->hi)) * ad_c.transpose() +
      between * range(a->hi, b->lo) * between.transpose() +
      ad_a * (range(high_from, std::max(a->hi, b->hi)) + a->h + b->h) * ad_a.transpose();
  return result;
}

Cycle CycleTest::cycle(std::size_t k) const {
  // Y = Y^ Exp(Ad(X^_hi) n - xi_hi) with the chain anchored at lo: the covariance transported by
  // Ad(Y), which leaves the distance of Log(Y) unchanged (Ad(Y) Log(Y) = Log(Y)).
  if (!closes_cycle(k))
    throw std::invalid_argument("cycle: closure " + std::to_string(k) +
                                " joins two sessions: it closes no cycle alone");
  const Closure& a = closure_[k];
  const Eigen::Matrix3d ad = adjoint(a.x, a.y, a.c, a.s);
  Cycle result;
  result.residual = se2_log(a.x, a.y, a.theta, a.c, a.s);
  result.covariance = ad * (prefix_[a.hi] - prefix_[a.lo] + a.h) * ad.transpose();
  return result;
}

double CycleTest::distance(const Cycle& cycle) const {
  const double heading_variance = cycle.covariance(2, 2);
  if (heading_variance > linear_heading_variance_)
    return cycle.residual.z() * cycle.residual.z() / heading_variance * heading_only_factor_;
  return mahalanobis_squared(cycle.residual, cycle.covariance);
}

double CycleTest::squared_distance(std::size_t k, std::size_t l) const {
  return closes_cycle(k, l) ? distance(cycle(k, l)) : 0.0;
}

double CycleTest::squared_distance(std::size_t k) const {
  return closes_cycle(k) ? distance(cycle(k)) : 0.0;
}

ConsistencyGraph pairwise_consistency(const PoseGraph& graph, const ChainSplit& split,
                                      const ConsistencySettings& settings) {
  const CycleTest test(graph, split, settings);
  ConsistencyGraph result;
  result.threshold = chi_square3_quantile(settings.confidence);
  const std::size_t m = test.closures();
  result.closures = m;
  // Blocks of consecutive rows with about equal numbers of pairs; each block fills its own list,
  // and the lists are joined in block order, so the result is the same on every backend.
  constexpr std::size_t kBlocks = 64;
  std::vector<std::size_t> first_row{0};
  const double pairs_per_block = 0.5 * static_cast<double>(m) * static_cast<double>(m) / kBlocks;
  double pairs = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    pairs += static_cast<double>(m - 1 - k);
    if (pairs >= pairs_per_block * static_cast<double>(first_row.size()))
      first_row.push_back(k + 1);
  }
  if (first_row.back() != m) first_row.push_back(m);
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> found(first_row.size() - 1);
  result.odometry_consistent.resize(m);
  for (std::size_t k = 0; k < m; ++k)
    result.odometry_consistent[k] = test.squared_distance(k) <= result.threshold;
  aco::with_backend(settings.backend, settings.threads, [&](auto backend) {
    backend.for_each(found.size(), [&](std::size_t block) {
      for (std::size_t k = first_row[block]; k < first_row[block + 1]; ++k) {
        if (!result.odometry_consistent[k]) continue;
        for (std::size_t l = k + 1; l < m; ++l)
          if (result.odometry_consistent[l] && test.squared_distance(k, l) <= result.threshold)
            found[block].emplace_back(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(l));
      }
    });
  });
  std::size_t total = 0;
  for (const auto& block : found) total += block.size();
  result.pairs.reserve(total);
  for (auto& block : found) {
    result.pairs.insert(result.pairs.end(), block.begin(), block.end());
    block = {};  // its memory back before the next block is copied
  }
  return result;
}

ConsistencyGraph pairwise_consistency(const FragmentSet& set, const ConsistencySettings& settings) {
  validate(set);
  std::vector<Pose2> means;
  for (std::size_t i = 1; i < set.fragments.size(); ++i)
    means.push_back(set.fragments[i].alignment->mean());
  const PoseGraph graph = pose_graph_of(set, chain(means));
  return pairwise_consistency(graph, split_chain(graph, set.name), settings);
}

}  // namespace antslam::slam
