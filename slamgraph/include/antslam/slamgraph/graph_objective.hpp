#pragma once
// Eq. (10) on a pose graph as a smooth function of the vertex poses, with its analytic gradient:
// the objective of NLopt on pose graphs (graph_optimize.hpp). The terms are the oriented edges
// (graph_structure.hpp); the unknowns are the poses of the vertices that are not fixed,
// x = (x_v, y_v, theta_v) for each free vertex v in increasing order; fixed vertices stay at the
// graph's own poses. Angles may leave [-pi, pi): residuals are wrapped, and the wrap has
// derivative 1 almost everywhere.
//
// Gradient of one edge (i, j) = (lo, hi) with r = (R_i^T (t_j - t_i) - t_mu,
// theta_j - theta_i - theta_mu) and g = dW/dr: with d = R_i^T (t_j - t_i),
//   dW/dt_j = R_i g_xy,  dW/dt_i = -R_i g_xy,  dW/dtheta_j = g_theta,
//   dW/dtheta_i = g_x d_y - g_y d_x - g_theta.
// Kernel width s (graduated non-convexity, refine.hpp): each term s^2 (1 - exp(-m / (2 s^2))),
// m = r^T Omega r, its gradient e^{-m/(2 s^2)} Omega r; s = 1 is eq. (10).

#include <cstddef>
#include <span>
#include <vector>

#include "antslam/slamgraph/g2o.hpp"
#include "antslam/slamgraph/graph_structure.hpp"

namespace antslam::slam {

class GraphObjective {
 public:
  /// Throws std::invalid_argument for a graph whose fixed vertices are not in it.
  explicit GraphObjective(const PoseGraph& graph);

  std::size_t dimension() const { return 3 * free_.size(); }

  /// Eq. (10) weight (widened with a kernel width other than 1) and chi2 at x; fills `gradient`
  /// (same size as x) unless empty. Not thread-safe (scratch memory).
  Scores evaluate(std::span<const double> x, std::span<double> gradient = {});

  /// Sets the kernel width s (> 0; 1 = eq. (10)).
  void set_kernel_width(double width);
  double kernel_width() const { return width_; }

  /// The free vertices' poses of `poses` (one per vertex) as x.
  std::vector<double> pack(std::span<const Pose2> poses) const;
  /// Every vertex's pose for x: the fixed ones from the graph.
  std::vector<Pose2> unpack(std::span<const double> x) const;

 private:
  const PoseGraph* graph_;
  std::vector<OrientedEdge> edges_;
  double width_ = 1.0;
  std::vector<std::size_t> free_;     // free vertices, ascending
  std::vector<std::ptrdiff_t> slot_;  // per vertex: its index in free_, or -1 when fixed
  std::vector<double> poses_;         // scratch: (x, y, theta) of every vertex
};

}  // namespace antslam::slam
