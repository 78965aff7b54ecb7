#pragma once
// Helpers of the slamgraph tests. Small random fragment sets: arbitrary alignments, correlated
// covariances, random anchors and several loop closures, so that nothing relies on the
// structure the synthetic generator happens to have. And the message of an expected error.

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

#include "antslam/aco/random.hpp"
#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/fragment_set_io.hpp"

namespace antslam::slam::testing {

/// A random symmetric positive definite covariance with standard deviations around `scale`
/// (x, y) and `scale / 5` (theta), and correlations up to ~0.6.
inline Eigen::Matrix3d random_covariance(aco::Rng& rng, double scale) {
  Eigen::Matrix3d a;
  for (int i = 0; i < 9; ++i) a(i / 3, i % 3) = rng.uniform() - 0.5;
  const Eigen::Vector3d sd(scale * (0.5 + rng.uniform()), scale * (0.5 + rng.uniform()),
                           0.2 * scale * (0.5 + rng.uniform()));
  Eigen::Matrix3d c = 0.5 * (a + a.transpose()) + 1.5 * Eigen::Matrix3d::Identity();
  const Eigen::Vector3d d = c.diagonal().cwiseSqrt().cwiseInverse();
  c = d.asDiagonal() * c * d.asDiagonal();  // a correlation matrix
  return sd.asDiagonal() * c * sd.asDiagonal();
}

inline Pose2 random_pose(aco::Rng& rng, double extent) {
  return {extent * (2.0 * rng.uniform() - 1.0), extent * (2.0 * rng.uniform() - 1.0),
          wrap_angle(6.3 * rng.uniform())};
}

/// N fragments, M samples each, `closures` closures between random pairs (the first one is the
/// paper's (0, N-1)); hypotheses near the chain of the means so that weights are not all 1.
inline FragmentSet random_set(std::size_t n, std::size_t m, std::size_t closures,
                              std::uint64_t seed, double scale = 0.3) {
  aco::Rng rng(aco::mix_seed(seed, 77));
  FragmentSet set;
  set.name = "random";
  set.fragments.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Fragment& f = set.fragments[i];
    f.exit = random_pose(rng, 2.0);
    if (i == 0) continue;
    const Gaussian2 g(random_pose(rng, 3.0), random_covariance(rng, scale));
    f.alignment = g;
    for (std::size_t j = 0; j < m; ++j) f.samples.push_back(g.sample(rng));
  }
  std::vector<Pose2> means;
  for (std::size_t i = 1; i < n; ++i) means.push_back(set.fragments[i].alignment->mean());
  const std::vector<Pose2> frames = chain(means);
  for (std::size_t c = 0; c < closures; ++c) {
    LoopClosure lc;
    if (c == 0) {
      lc.from = 0;
      lc.to = n - 1;
    } else {
      lc.to = 1 + rng.below(static_cast<std::uint32_t>(n - 1));
      lc.from = rng.below(static_cast<std::uint32_t>(lc.to));
    }
    lc.anchor = random_pose(rng, 1.0);
    const Gaussian2 noise(Pose2{}, random_covariance(rng, scale));
    const Pose2 near = closure_pose(lc, frames);
    lc.hypothesis = Gaussian2(Pose2::from_vector(near.vector() + noise.sample(rng).vector()),
                              random_covariance(rng, 2.0 * scale));
    set.closures.push_back(lc);
  }
  validate(set);
  return set;
}

/// The set as its file text.
inline std::string fragment_set_text(const FragmentSet& set) {
  std::ostringstream out;
  write_fragment_set(out, set);
  return out.str();
}

/// The message of the std::runtime_error that f() throws, or "no error".
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace antslam::slam::testing
