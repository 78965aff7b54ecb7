#include "antslam/slamgraph/synth.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "antslam/aco/random.hpp"

namespace antslam::slam {

namespace {

/// Pose at arc length s along the rectangle (any s; it wraps), relative to the start.
class Rectangle {
 public:
  Rectangle(double perimeter, double aspect)
      : height_(perimeter / (2.0 * (1.0 + aspect))), width_(aspect * height_) {
    start_ = absolute(0.0);
  }

  Pose2 at(double s) const { return between(start_, absolute(s)); }

 private:
  /// Counter-clockwise from the bottom-left corner; the start is mid-way along the bottom.
  Pose2 absolute(double s) const {
    const double perimeter = 2.0 * (width_ + height_);
    double u = std::fmod(s + 0.5 * width_, perimeter);
    if (u < 0.0) u += perimeter;
    constexpr double kQuarter = std::numbers::pi / 2.0;
    if (u < width_) return {u, 0.0, 0.0};
    u -= width_;
    if (u < height_) return {width_, u, kQuarter};
    u -= height_;
    if (u < width_) return {width_ - u, height_, wrap_angle(2.0 * kQuarter)};
    u -= width_;
    return {0.0, height_ - u, -kQuarter};
  }

  double height_, width_;
  Pose2 start_;
};

Eigen::Matrix3d covariance(double sigma_xy, double sigma_theta, double correlation) {
  const Eigen::Vector3d sd(sigma_xy, sigma_xy, sigma_theta);
  Eigen::Matrix3d c = Eigen::Matrix3d::Constant(correlation);
  c.diagonal().setOnes();
  return sd.asDiagonal() * c * sd.asDiagonal();
}

/// p + noise drawn from N(0, Sigma), or p itself when noise-free.
Pose2 perturb(const Pose2& p, const Gaussian2& noise, aco::Rng& rng, bool noise_free) {
  if (noise_free) return p;
  const Pose2 d = noise.sample(rng);
  return Pose2::from_vector(p.vector() + d.vector());
}

void check(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("synth: ") + what);
}

}  // namespace

SynthSettings synth_preset(std::string_view name) {
  SynthSettings s;
  if (name == "paper9") {
    s.fragments = 9, s.loop_length_m = 53.0, s.aspect = 22.0 / 14.0;
  } else if (name == "paper15") {
    s.fragments = 15, s.loop_length_m = 82.0, s.aspect = 22.0 / 24.0;
  } else if (name == "paper24") {
    s.fragments = 24, s.loop_length_m = 137.0, s.aspect = 51.0 / 24.0;
  } else {
    throw std::invalid_argument("unknown preset '" + std::string(name) +
                                "' (expected paper9, paper15 or paper24)");
  }
  s.samples = 20;
  return s;
}

FragmentSet synthesize(const SynthSettings& s) {
  check(s.fragments >= 2 && s.fragments <= kMaxSynthFragments, "fragments must be in [2, 1000000]");
  check(s.samples >= 1 && s.samples <= kMaxSynthSamples, "samples must be in [1, 1000000]");
  check(s.laps >= 1 && s.laps <= 1000, "laps must be in [1, 1000]");
  check(s.laps == 1 || s.fragments <= kMaxRevisitFragments,
        "more than one lap checks every pair of fragments for a revisit: at most 20000 fragments");
  check(s.loop_length_m > 0.0 && s.loop_length_m <= 1e6, "loop length must be in (0, 1e6] m");
  check(s.aspect >= 1e-3 && s.aspect <= 1e3, "aspect must be in [0.001, 1000]");
  check(s.sigma_xy > 0.0 && s.sigma_xy <= 1e3 && s.sigma_theta > 0.0 && s.sigma_theta <= 10.0,
        "alignment sigmas must be in (0, 1000] m and (0, 10] rad");
  check(s.closure_sigma_xy > 0.0 && s.closure_sigma_xy <= 1e3 && s.closure_sigma_theta > 0.0 &&
            s.closure_sigma_theta <= 10.0,
        "closure sigmas must be in (0, 1000] m and (0, 10] rad");
  check(s.correlation > -0.5 && s.correlation < 1.0, "correlation must be in (-0.5, 1)");
  check(s.revisit_radius_m >= 0.0 && s.revisit_radius_m <= s.loop_length_m,
        "revisit radius must be in [0, loop length]");
  check(s.trajectory_poses <= 10000, "trajectory poses must be at most 10000 per fragment");

  const Rectangle path(s.loop_length_m, s.aspect);
  const std::size_t n = s.fragments;
  const double total = s.loop_length_m * static_cast<double>(s.laps);
  const double spacing = total / static_cast<double>(n);
  const Gaussian2 alignment_noise(Pose2{}, covariance(s.sigma_xy, s.sigma_theta, s.correlation));
  const Gaussian2 closure_noise(Pose2{},
                                covariance(s.closure_sigma_xy, s.closure_sigma_theta, 0.0));
  aco::Rng noise_rng(aco::mix_seed(s.seed, 1));
  aco::Rng sample_rng(aco::mix_seed(s.seed, 2));

  FragmentSet set;
  std::ostringstream name;
  name << "synthetic: N=" << n << " M=" << s.samples << " loop=" << s.loop_length_m
       << "m laps=" << s.laps << " sigma=(" << s.sigma_xy << "m, " << s.sigma_theta
       << "rad) seed=" << s.seed << (s.noise_free ? " noise-free" : "");
  set.name = name.str();
  for (std::size_t i = 0; i < n; ++i) set.reference.push_back(path.at(spacing * double(i)));
  set.fragments.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Fragment& f = set.fragments[i];
    const Pose2& frame = set.reference[i];
    for (std::size_t k = 0; k < s.trajectory_poses; ++k) {
      const double arc = spacing * (double(i) + double(k) / double(s.trajectory_poses));
      f.trajectory.push_back({arc, between(frame, path.at(arc))});
    }
    if (i == 0) continue;
    const Pose2 truth = between(set.reference[i - 1], frame);
    const Gaussian2 g(perturb(truth, alignment_noise, noise_rng, s.noise_free),
                      alignment_noise.covariance());
    f.alignment = g;
    for (std::size_t j = 0; j < s.samples; ++j) f.samples.push_back(g.sample(sample_rng));
    set.fragments[i - 1].exit = g.mean();  // eq. (4): F_i starts at E_{i-1}
  }
  set.fragments[n - 1].exit = between(set.reference[n - 1], path.at(total));
  const Eigen::Matrix3d closure_cov = closure_noise.covariance();
  const auto close = [&](std::size_t a, std::size_t b, const Pose2& anchor) {
    const Pose2 truth = between(set.reference[a], set.reference[b] * anchor);
    set.closures.push_back(
        {a, b, anchor,
         Gaussian2(perturb(truth, closure_noise, noise_rng, s.noise_free), closure_cov)});
  };
  close(0, n - 1, set.fragments[n - 1].exit);  // the paper's loop: E_N back at the start
  // With several laps, every revisit closes a loop: count them first, then make them.
  const auto for_each_revisit = [&](auto&& f) {
    for (std::size_t b = 2; b < n && s.laps > 1; ++b)
      for (std::size_t a = 0; a + 2 <= b; ++a) {
        if (a == 0 && b == n - 1) continue;
        const Pose2 d = between(set.reference[a], set.reference[b]);
        if (std::hypot(d.x, d.y) < s.revisit_radius_m) f(a, b);
      }
  };
  std::size_t revisits = 0;
  for_each_revisit([&](std::size_t, std::size_t) { ++revisits; });
  check(revisits <= kMaxSynthClosures,
        "the revisit radius makes more than 1000000 loop closures; choose a smaller one");
  for_each_revisit([&](std::size_t a, std::size_t b) { close(a, b, Pose2{}); });
  return set;
}

}  // namespace antslam::slam
