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
// xi_{k+1} = xi_k + Ad(X^_{k+1}) m_k, Ad(T) = [R, (t_y, -t_x)^T; 0, 1]. A closure (a < b, z) has
// the correction Y = X^_a z X^_b^-1, the identity when closure and odometry agree. The residual of
// a cycle C is Log(C) (exponential coordinates: a drifted odometry makes C far from the identity,
// where (x, y, theta) of C and Log(C) differ). The cycle of closures A and B (lo_A <= lo_B) is
// C = Y_A Y_B^-1; anchoring the chain at lo_A (the steps before it only conjugate C), its left
// perturbation to first order is
//   Ad(Y_A) [Ad(X^_hA) n_A - Ad(X^_hB) n_B + xi_hB - xi_hA] - Ad(C) xi_lB,
// so a step k, G_k = Ad(X^_{k+1}) Sigma_k Ad(X^_{k+1})^T, enters the covariance as
//   Ad(C) G_k Ad(C)^T                      in [lo_A, min(lo_B, hi_A)) (before the overlap),
//   (Ad(Y_A) - Ad(C)) G_k (...)^T          in [hi_A, lo_B) (between disjoint spans),
//   Ad(Y_A) G_k Ad(Y_A)^T                  between the two high ends,
// and not at all in the overlap, where the two spans cancel; both closures' own terms
// H = Ad(X^_hi) Sigma_z Ad(X^_hi)^T enter as Ad(Y_A) H Ad(Y_A)^T. Prefix sums S_b = sum_{k<b} G_k
// give each range in O(1). Positions are taken about their centroid to keep the Ad terms small.
//
// Where the cycle's heading standard deviation exceeds linear_heading_sd, the first-order
// translation covariance no longer describes the cycle: a heading error theta at lever r moves
// the translation r (1 - cos theta) towards the centre, a banana the ellipse leaves out, and at
// heading deviations of a radian the 3-dof test rejects right closures. There the test is on the
// heading alone (its distance does not depend on the frame): its 1-dof distance scaled so that it
// meets the 3-dof threshold exactly when it meets the 1-dof threshold of the same confidence.
// The regime is the noise's, not the statement's (a graph stating 0.09 rad per step whose steps
// show 0.002 rad is linear over hundreds of steps), so the rule applies only where the tested
// covariances are the noise the graph shows (ConsistencySettings::linear_heading_sd;
// shown_noise.hpp, robust.hpp).

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "antslam/aco/backend_kind.hpp"
#include "antslam/slamgraph/chain.hpp"
#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/g2o.hpp"

namespace antslam::slam {

/// Beyond this heading standard deviation of a cycle (radians) the test is on its heading alone.
inline constexpr double kLinearHeadingSd = 0.5;

struct ConsistencySettings {
  double confidence = 0.99;  ///< probability that two right closures pass the test (0, 1)
  aco::BackendKind backend = aco::BackendKind::automatic;  ///< backend spreading the pairs
  std::size_t threads = 1;                                 ///< its threads; 0 = all cores
  double linear_heading_sd =
      std::numeric_limits<double>::infinity();  ///< beyond this heading
                                                ///< deviation of a cycle (radians, at the tested
                                                ///< covariances), the heading alone: only where the
                                                ///< covariances are the noise the graph shows
                                                ///< (kLinearHeadingSd; robust.hpp)
};

struct ConsistencyGraph {
  std::size_t closures = 0;  ///< vertices: the loop closures, in the order of split.closures
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  ///< consistent (k, l), k < l,
                                                               ///< increasing
  std::vector<bool> odometry_consistent;  ///< per closure: passes the unary test
  double threshold = 0.0;                 ///< the chi-square threshold on the squared distance
};

/// The residual Log(C) of a cycle and the first-order covariance of its left perturbation.
struct Cycle {
  Eigen::Vector3d residual = Eigen::Vector3d::Zero();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
};

/// The squared distances of the cycles of the closures of a graph (indices into
/// split.closures), for tests and diagnostics; pairwise_consistency computes the same values.
class CycleTest {
 public:
  /// Of `settings`, the confidence and linear_heading_sd. Throws std::invalid_argument for a
  /// confidence outside (0, 1) or a linear_heading_sd that is not positive.
  /// On a multi-session graph (split_sessions) closures within a session are tested as on one
  /// chain; two closures between the same two sessions close a cycle through both sessions'
  /// odometry (Mangelson et al. 2018); any other pair, and a closure between sessions alone,
  /// closes none.
  CycleTest(const PoseGraph& graph, const ChainSplit& split,
            const ConsistencySettings& settings = {});
  std::size_t closures() const { return closure_.size(); }
  /// Whether closures k and l close a cycle (with the odometry).
  bool closes_cycle(std::size_t k, std::size_t l) const;
  /// Whether closure k closes a cycle with the odometry (it joins a session to itself).
  bool closes_cycle(std::size_t k) const;
  /// The cycle of closures k and l; throws std::invalid_argument if they close none.
  Cycle cycle(std::size_t k, std::size_t l) const;
  /// The cycle of closure k with the odometry between its ends (Y_k); throws
  /// std::invalid_argument if it closes none.
  Cycle cycle(std::size_t k) const;
  /// The squared Mahalanobis distance of the cycle of closures k and l, or its heading-only
  /// equivalent (above); 0 (consistent) if they close none.
  double squared_distance(std::size_t k, std::size_t l) const;
  /// The same for the cycle of closure k with the odometry between its ends.
  double squared_distance(std::size_t k) const;

 private:
  struct Closure {
    std::size_t lo = 0, hi = 0;                    // the chain steps lo..hi-1 lie between its ends
    std::size_t from_session = 0, to_session = 0;  // the sessions of lo and hi
    double x = 0, y = 0, c = 1, s = 0;  // correction Y: translation, cos and sin of its angle
    double theta = 0;
    Eigen::Matrix3d h;  // Ad(X^_hi) Sigma Ad(X^_hi)^T
  };
  double distance(const Cycle& cycle) const;
  std::vector<Closure> closure_;
  std::vector<Eigen::Matrix3d> prefix_;   // S_b, b = 0..n-1
  double heading_only_factor_ = 1.0;      // 3-dof over 1-dof threshold at the confidence
  double linear_heading_variance_ = 0.0;  // linear_heading_sd squared
};

/// Pairs that close no cycle (other sessions, CycleTest) are consistent. Throws
/// std::invalid_argument for a confidence outside (0, 1) or serial on several threads.
ConsistencyGraph pairwise_consistency(const PoseGraph& graph, const ChainSplit& split,
                                      const ConsistencySettings& settings = {});

/// The same for a fragment set: its alignments are the chain and its loop closures the closures,
/// in set.closures order (through pose_graph_of). Throws std::invalid_argument for an invalid
/// set.
ConsistencyGraph pairwise_consistency(const FragmentSet& set,
                                      const ConsistencySettings& settings = {});

}  // namespace antslam::slam
