#include "antslam/slamgraph/alignment_objective.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace antslam::slam {

AlignmentObjective::AlignmentObjective(const FragmentSet& set) {
  validate(set);
  for (std::size_t i = 1; i < set.fragments.size(); ++i) {
    const Gaussian2& g = *set.fragments[i].alignment;
    alignments_.push_back({g.mean(), g.information()});
  }
  for (const LoopClosure& c : set.closures)
    closures_.push_back(
        {c.from, c.to, c.anchor, {c.hypothesis.mean(), c.hypothesis.information()}});
  frames_.resize(set.fragments.size());
  v_change_.resize(set.fragments.size() + 1);
  s_change_.resize(set.fragments.size() + 1);
}

std::vector<double> AlignmentObjective::pack(std::span<const Pose2> alignments) {
  std::vector<double> x;
  x.reserve(3 * alignments.size());
  for (const Pose2& p : alignments) x.insert(x.end(), {p.x, p.y, p.theta});
  return x;
}

std::vector<Pose2> AlignmentObjective::unpack(std::span<const double> x) {
  if (x.size() % 3 != 0)
    throw std::invalid_argument("alignment vector size is not a multiple of 3");
  std::vector<Pose2> alignments(x.size() / 3);
  for (std::size_t i = 0; i < alignments.size(); ++i)
    alignments[i] = Pose2::from_vector({x[3 * i], x[3 * i + 1], x[3 * i + 2]});
  return alignments;
}

void AlignmentObjective::set_kernel_width(double width) {
  if (!(width > 0.0) || !std::isfinite(width))
    throw std::invalid_argument("kernel width must be a positive number");
  width_ = width;
}

Eigen::Vector3d AlignmentObjective::add_term(const Term& term, const Eigen::Vector3d& residual,
                                             Scores& scores) const {
  const Eigen::Vector3d omega_r = term.information * residual;
  const double m = residual.dot(omega_r);
  const double w2 = width_ * width_;
  // The peak-normalised N(mu, Sigma)(.) of eq. (10), at width 1.
  const double value = std::exp(-0.5 * m / w2);
  scores.chi2 += m;
  scores.weight += w2 * (1.0 - value);
  return value * omega_r;  // d(s^2 (1 - exp(-m/(2 s^2))))/dr
}

Scores AlignmentObjective::evaluate(std::span<const double> x, std::span<double> gradient) {
  if (x.size() != dimension())
    throw std::invalid_argument("alignment vector has " + std::to_string(x.size()) +
                                " entries, expected " + std::to_string(dimension()));
  const bool with_gradient = !gradient.empty();
  if (with_gradient && gradient.size() != x.size())
    throw std::invalid_argument("gradient size differs from the alignment vector");
  Scores scores;
  // Alignment terms and the chain of eq. (8).
  frames_[0] = {0.0, 0.0, 0.0, 1.0, 0.0};
  for (std::size_t i = 0; i < alignments_.size(); ++i) {
    const double* xi = x.data() + 3 * i;
    const Pose2& mu = alignments_[i].mean;
    const Eigen::Vector3d r(xi[0] - mu.x, xi[1] - mu.y, wrap_angle(xi[2] - mu.theta));
    const Eigen::Vector3d g = add_term(alignments_[i], r, scores);
    if (with_gradient) std::copy(g.data(), g.data() + 3, gradient.data() + 3 * i);
    const ChainFrame& p = frames_[i];
    const double theta = p.theta + xi[2];
    frames_[i + 1] = {p.x + p.c * xi[0] - p.s * xi[1], p.y + p.s * xi[0] + p.c * xi[1], theta,
                      std::cos(theta), std::sin(theta)};
  }
  // Closure terms; their gradient goes to the difference arrays over k in (a, b].
  if (with_gradient) {
    std::fill(v_change_.begin(), v_change_.end(), Eigen::Vector2d::Zero());
    std::fill(s_change_.begin(), s_change_.end(), 0.0);
  }
  for (const ClosureTerm& c : closures_) {
    const ChainFrame& fa = frames_[c.from];
    const ChainFrame& fb = frames_[c.to];
    const Eigen::Vector2d tg(fb.x + fb.c * c.anchor.x - fb.s * c.anchor.y,
                             fb.y + fb.s * c.anchor.x + fb.c * c.anchor.y);
    const double dx = tg.x() - fa.x, dy = tg.y() - fa.y;
    const Pose2& h = c.hypothesis.mean;
    const Eigen::Vector3d r(fa.c * dx + fa.s * dy - h.x, -fa.s * dx + fa.c * dy - h.y,
                            wrap_angle(fb.theta + c.anchor.theta - fa.theta - h.theta));
    const Eigen::Vector3d g = add_term(c.hypothesis, r, scores);
    if (!with_gradient) continue;
    const Eigen::Vector2d v(fa.c * g.x() - fa.s * g.y(), fa.s * g.x() + fa.c * g.y());
    const double sigma = v.y() * tg.x() - v.x() * tg.y() + g.z();  // v . J t_G + g_theta
    v_change_[c.from + 1] += v;
    v_change_[c.to + 1] -= v;
    s_change_[c.from + 1] += sigma;
    s_change_[c.to + 1] -= sigma;
  }
  if (!with_gradient) return scores;
  Eigen::Vector2d v_sum = Eigen::Vector2d::Zero();
  double s_sum = 0.0;
  for (std::size_t k = 1; k < frames_.size(); ++k) {
    v_sum += v_change_[k];
    s_sum += s_change_[k];
    const ChainFrame& prev = frames_[k - 1];
    const ChainFrame& fk = frames_[k];
    double* gk = gradient.data() + 3 * (k - 1);
    gk[0] += prev.c * v_sum.x() + prev.s * v_sum.y();  // R_{k-1}^T v
    gk[1] += -prev.s * v_sum.x() + prev.c * v_sum.y();
    gk[2] += s_sum - (v_sum.y() * fk.x - v_sum.x() * fk.y);  // - v . J t_{F_k}
  }
  return scores;
}

}  // namespace antslam::slam
