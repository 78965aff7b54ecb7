#pragma once
// Shared by the robust back ends (robust.cpp, robust_gnc.cpp, robust_pcm.cpp).

#include <chrono>
#include <vector>

#include "antslam/slamgraph/ceres_baseline.hpp"
#include "antslam/slamgraph/chain.hpp"
#include "antslam/slamgraph/g2o.hpp"
#include "antslam/slamgraph/robust.hpp"

namespace antslam::slam::detail {

/// Seconds since `start`.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The squared loss on odometry, closure_loss[k] on closure k.
std::vector<EdgeLoss> edge_losses(const PoseGraph& graph, const ChainSplit& split,
                                  const std::vector<EdgeLoss>& closure_loss);

/// Ceres from `initial` with the given losses; adds its time to result.optimize_s, stores the
/// poses in result.poses and returns the final cost.
double optimize(const PoseGraph& graph, const std::vector<Pose2>& initial,
                const std::vector<EdgeLoss>& losses, const RobustSettings& settings,
                RobustResult& result);

/// The squared residual r^T Omega r of every closure at `poses`, in split order.
std::vector<double> closure_chi2(const PoseGraph& graph, const ChainSplit& split,
                                 const std::vector<Pose2>& poses);

/// Per closure: whether its squared residual at `poses` passes the chi-square test c2.
std::vector<bool> closures_within(const PoseGraph& graph, const ChainSplit& split,
                                  const std::vector<Pose2>& poses, double c2);

void run_gnc(const PoseGraph& graph, const std::vector<Pose2>& initial, double c2,
             const RobustSettings& settings, RobustResult& result);

void run_pcm(const PoseGraph& graph, const std::vector<Pose2>& initial, double c2,
             const RobustSettings& settings, RobustResult& result);

}  // namespace antslam::slam::detail
