#pragma once
// Eq. (10) as a smooth function of the continuous alignments, with its analytic gradient: the
// objective of the NLopt refinement (and, up to Ceres' factor, of the robust Ceres baseline).
//
// Parameters: x = (x_1, y_1, theta_1, ..., x_{N-1}, y_{N-1}, theta_{N-1}), alignment X_i = pose
// of F_i in F_{i-1} (fragment_set.hpp). Angles may leave [-pi, pi): residuals are wrapped and
// the wrap has derivative 1 almost everywhere.
//
// Gradient of a closure term (a, b, anchor A): with F_k = X_1 ... X_k, G = F_b A (the anchor in
// W), r = (R_a^T (t_G - t_a) - t_H, theta_G - theta_a - theta_H) and g = dW/dr = e^{-m/2} Omega r,
// put v = R_a g_xy. Then for every a < k <= b
//   dW/d(x_k, y_k) = R_{k-1}^T v,    dW/dtheta_k = v . J (t_G - t_{F_k}) + g_theta,
// J the 90-degree rotation. Both are sums over the closures covering k, so one difference array
// per quantity makes the whole gradient O(N + closures).
//
// Kernel width (graduated non-convexity, refine.hpp): with width s every term becomes
// s^2 (1 - exp(-m / (2 s^2))), m = r^T Omega r, and its gradient e^{-m/(2 s^2)} Omega r. Width 1 is
// eq. (10); as s grows the sum tends to chi2 / 2 (least squares), whose basin reaches everywhere.

#include <cstddef>
#include <span>
#include <vector>

#include "antslam/slamgraph/fragment_set.hpp"

namespace antslam::slam {

class AlignmentObjective {
 public:
  /// Validates the set (std::invalid_argument naming the problem).
  explicit AlignmentObjective(const FragmentSet& set);

  std::size_t dimension() const { return 3 * alignments_.size(); }

  /// Eq. (10) weight and chi2 at x; fills `gradient` (dW/dx, same size as x) unless empty.
  /// With a kernel width other than 1, `weight` is the widened sum (above). Not thread-safe
  /// (reuses scratch memory); use one object per thread.
  Scores evaluate(std::span<const double> x, std::span<double> gradient = {});

  /// Sets the kernel width s (> 0; 1 = eq. (10)).
  void set_kernel_width(double width);
  double kernel_width() const { return width_; }

  static std::vector<double> pack(std::span<const Pose2> alignments);
  static std::vector<Pose2> unpack(std::span<const double> x);

 private:
  struct Term {
    Pose2 mean;
    Eigen::Matrix3d information;
  };
  struct ClosureTerm {
    std::size_t from;
    std::size_t to;
    Pose2 anchor;
    Term hypothesis;
  };
  struct ChainFrame {
    double x, y, theta, c, s;
  };

  /// Adds s^2 (1 - exp(-m/(2 s^2))) and m to `scores`; returns dW/dr.
  Eigen::Vector3d add_term(const Term& term, const Eigen::Vector3d& residual, Scores& scores) const;

  double width_ = 1.0;  // kernel width s
  std::vector<Term> alignments_;
  std::vector<ClosureTerm> closures_;
  std::vector<ChainFrame> frames_;         // scratch: F_0..F_{N-1}
  std::vector<Eigen::Vector2d> v_change_;  // scratch: difference array of v
  std::vector<double> s_change_;           // scratch: difference array of v.J t_G + g_theta
};

}  // namespace antslam::slam
