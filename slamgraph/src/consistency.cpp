#include "antslam/slamgraph/consistency.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "antslam/aco/backend_factory.hpp"
#include "antslam/slamgraph/chi_square.hpp"

namespace antslam::slam {

namespace {

using Symmetric3 = std::array<double, 6>;

/// The upper triangle (xx xy xt yy yt tt) of Ad(T) Sigma Ad(T)^T.
Symmetric3 adjoint_covariance(const Pose2& t, const Eigen::Matrix3d& covariance) {
  const double c = std::cos(t.theta), s = std::sin(t.theta);
  Eigen::Matrix3d ad;
  ad << c, -s, t.y, s, c, -t.x, 0.0, 0.0, 1.0;
  const Eigen::Matrix3d m = ad * covariance * ad.transpose();
  return {m(0, 0), m(0, 1), m(0, 2), m(1, 1), m(1, 2), m(2, 2)};
}

/// e^T C^-1 e for the symmetric C = (xx xy xt yy yt tt) by LDL^T; +infinity unless C is
/// positive definite.
double mahalanobis_squared(const std::array<double, 3>& e, const Symmetric3& c) {
  const double d1 = c[0];
  if (!(d1 > 0.0)) return std::numeric_limits<double>::infinity();
  const double l21 = c[1] / d1, l31 = c[2] / d1;
  const double d2 = c[3] - l21 * c[1];
  if (!(d2 > 0.0)) return std::numeric_limits<double>::infinity();
  const double l32 = (c[4] - l31 * c[1]) / d2;
  const double d3 = c[5] - l31 * c[2] - l32 * l32 * d2;
  if (!(d3 > 0.0)) return std::numeric_limits<double>::infinity();
  const double y1 = e[0], y2 = e[1] - l21 * y1, y3 = e[2] - l31 * y1 - l32 * y2;
  return y1 * y1 / d1 + y2 * y2 / d2 + y3 * y3 / d3;
}

}  // namespace

CycleTest::CycleTest(const PoseGraph& graph, const ChainSplit& split) {
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
  prefix_.assign(pose.size(), Symmetric3{});
  for (std::size_t k = 0; k < split.chain.size(); ++k) {
    const Symmetric3 g =
        adjoint_covariance(pose[k + 1], oriented(graph.edges[split.chain[k]], k).covariance());
    for (std::size_t i = 0; i < 6; ++i) prefix_[k + 1][i] = prefix_[k][i] + g[i];
  }
  for (const std::size_t e : split.closures) {
    const PoseGraphEdge& edge = graph.edges[e];
    Closure c;
    c.lo = std::min(edge.from, edge.to);
    c.hi = std::max(edge.from, edge.to);
    const Gaussian2 z = oriented(edge, c.lo);
    const Pose2 y = pose[c.lo] * z.mean() * pose[c.hi].inverse();
    const Pose2 y_inverse = y.inverse();
    c.x = y.x;
    c.y = y.y;
    c.theta = y.theta;
    c.c = std::cos(y.theta);
    c.s = std::sin(y.theta);
    c.ix = y_inverse.x;
    c.iy = y_inverse.y;
    c.itheta = y_inverse.theta;
    c.h = adjoint_covariance(pose[c.hi], z.covariance());
    closure_.push_back(c);
  }
}

double CycleTest::squared_distance(std::size_t k, std::size_t l) const {
  const Closure& a = closure_[k];
  const Closure& b = closure_[l];
  // The cycle Y_a Y_b^-1.
  std::array<double, 3> e{a.x + a.c * b.ix - a.s * b.iy, a.y + a.s * b.ix + a.c * b.iy,
                          a.theta + b.itheta};
  if (e[2] >= std::numbers::pi) e[2] -= 2.0 * std::numbers::pi;
  if (e[2] < -std::numbers::pi) e[2] += 2.0 * std::numbers::pi;
  // Its covariance: both closures plus the chain steps in exactly one of the two spans.
  const std::size_t lo = std::max(a.lo, b.lo), hi = std::min(a.hi, b.hi);
  Symmetric3 c;
  for (std::size_t i = 0; i < 6; ++i) {
    c[i] = a.h[i] + b.h[i] + (prefix_[a.hi][i] - prefix_[a.lo][i]) +
           (prefix_[b.hi][i] - prefix_[b.lo][i]);
    if (lo < hi) c[i] -= 2.0 * (prefix_[hi][i] - prefix_[lo][i]);
  }
  return mahalanobis_squared(e, c);
}

double CycleTest::squared_distance(std::size_t k) const {
  const Closure& a = closure_[k];
  Symmetric3 c;
  for (std::size_t i = 0; i < 6; ++i) c[i] = a.h[i] + prefix_[a.hi][i] - prefix_[a.lo][i];
  return mahalanobis_squared({a.x, a.y, a.theta}, c);
}

ConsistencyGraph pairwise_consistency(const PoseGraph& graph, const ChainSplit& split,
                                      const ConsistencySettings& settings) {
  if (!(settings.confidence > 0.0 && settings.confidence < 1.0))
    throw std::invalid_argument("pairwise consistency: confidence must be in (0, 1), got " +
                                std::to_string(settings.confidence));
  ConsistencyGraph result;
  result.threshold = chi_square3_quantile(settings.confidence);
  const CycleTest test(graph, split);
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
