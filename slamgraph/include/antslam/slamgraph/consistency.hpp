#pragma once
// Pairwise consistency of loop closures (PCM, Mangelson et al. 2018): two closures are
// consistent when the cycle they close with the odometry between their ends is near the
// identity: its squared Mahalanobis distance under the first-order covariance of the cycle lies
// below the chi-square (3 dof) quantile of `confidence`. The trusted closures are then a maximum
// clique of this consistency graph. As in single-robot PCM implementations (Kimera-RPGO), a
// closure must also be consistent with the odometry between its own ends (the same test on the
// cycle closure + odometry): otherwise it has no consistent pair. Without this unary test a false
// closure between nearby poses passes every pairwise test against closures with long spans.
//
// Constant work per pair. With world-frame left perturbations on SE(2), X = Exp(xi) X^ and a
// measurement z = z^ Exp(n), the odometry chain X^_{k+1} = X^_k u^_k moves the perturbation by
// xi_{k+1} = xi_k + Ad(X^_{k+1}) m_k, Ad(T) = [R, (t_y, -t_x)^T; 0, 1], and a closure (a < b, z)
// has the correction Y = X^_a z X^_b^-1, which is the identity when closure and odometry agree
// and else, to first order, Exp(sum_{a<=k<b} Ad(X^_{k+1}) m_k - Ad(X^_b) n). The cycle of two
// closures is Y_1 Y_2^-1 (up to conjugation), computed exactly; its covariance is
//   Ad Sigma_1 Ad^T + Ad Sigma_2 Ad^T + sum over the steps in one closure's span but not the
//   other's of G_k = Ad(X^_{k+1}) Sigma_k Ad(X^_{k+1})^T,
// since the steps both spans share cancel in the cycle. Prefix sums S_b = sum_{k<b} G_k give that
// sum in O(1): S-range(span 1) + S-range(span 2) - 2 S-range(overlap). Positions are taken about
// their centroid to keep the Ad terms small.

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "antslam/aco/backend_kind.hpp"
#include "antslam/slamgraph/chain.hpp"
#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/g2o.hpp"

namespace antslam::slam {

struct ConsistencySettings {
  double confidence = 0.99;  ///< probability that two right closures pass the test (0, 1)
  aco::BackendKind backend = aco::BackendKind::automatic;  ///< backend spreading the pairs
  std::size_t threads = 1;                                 ///< its threads; 0 = all cores
};

struct ConsistencyGraph {
  std::size_t closures = 0;  ///< vertices: the loop closures, in the order of split.closures
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  ///< consistent (k, l), k < l,
                                                               ///< increasing
  std::vector<bool> odometry_consistent;  ///< per closure: passes the unary test
  double threshold = 0.0;                 ///< the chi-square threshold on the squared distance
};

/// The squared Mahalanobis distance of the cycle of closures k and l (indices into
/// split.closures), for tests and diagnostics; pairwise_consistency computes the same value.
class CycleTest {
 public:
  CycleTest(const PoseGraph& graph, const ChainSplit& split);
  std::size_t closures() const { return closure_.size(); }
  /// The cycle of closures k and l.
  double squared_distance(std::size_t k, std::size_t l) const;
  /// The cycle of closure k with the odometry between its ends.
  double squared_distance(std::size_t k) const;

 private:
  struct Closure {
    std::size_t lo = 0, hi = 0;                    // the chain steps lo..hi-1 lie between its ends
    double x = 0, y = 0, c = 1, s = 0, theta = 0;  // correction Y
    double ix = 0, iy = 0, itheta = 0;             // Y^-1
    std::array<double, 6> h{};                     // Ad Sigma Ad^T: xx xy xt yy yt tt
  };
  std::vector<Closure> closure_;
  std::vector<std::array<double, 6>> prefix_;  // S_b, b = 0..n-1
};

/// Throws std::invalid_argument for a confidence outside (0, 1) or serial on several threads.
ConsistencyGraph pairwise_consistency(const PoseGraph& graph, const ChainSplit& split,
                                      const ConsistencySettings& settings = {});

/// The same for a fragment set: its alignments are the chain and its loop closures the closures,
/// in set.closures order (through pose_graph_of). Throws std::invalid_argument for an invalid
/// set.
ConsistencyGraph pairwise_consistency(const FragmentSet& set,
                                      const ConsistencySettings& settings = {});

}  // namespace antslam::slam
