#include "mapping/close_loops.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace antslam::mapping {

void validate(const ClosingSettings& s) {
  if (!(s.outlier_chi2 > 0.0) || !std::isfinite(s.outlier_chi2))
    throw std::invalid_argument("closing: outlier_chi2 must be a positive number");
  if (s.ceres.max_iterations <= 0)
    throw std::invalid_argument("closing: ceres.max_iterations must be positive");
}

Closing close_loops(const slam::FragmentSet& set, std::span<const slam::Pose2> start,
                    const ClosingSettings& settings) {
  validate(settings);
  if (start.size() != set.fragments.size())
    throw std::invalid_argument("closing: got " + std::to_string(start.size()) +
                                " frames, expected " + std::to_string(set.fragments.size()));
  Closing out;
  out.trusted.assign(set.closures.size(), true);
  const std::vector<slam::Pose2> initial = slam::relative_alignments(start);
  slam::FragmentSet subset = set;
  for (;;) {
    subset.closures.clear();
    for (std::size_t c = 0; c < set.closures.size(); ++c)
      if (out.trusted[c]) subset.closures.push_back(set.closures[c]);
    if (subset.closures.empty()) {  // nothing to close: the alignments' means
      out.frames = slam::chain(slam::mean_alignments(set));
      return out;
    }
    out.frames = slam::optimize_with_ceres(subset, initial, false, settings.ceres).frames;
    ++out.solves;
    // The trusted closure that agrees worst with the joint solution.
    double worst = 0.0;
    std::size_t worst_index = 0;
    for (std::size_t c = 0; c < set.closures.size(); ++c) {
      if (!out.trusted[c]) continue;
      const slam::LoopClosure& closure = set.closures[c];
      const double m2 =
          closure.hypothesis.mahalanobis_squared(slam::closure_pose(closure, out.frames));
      if (m2 > worst) {
        worst = m2;
        worst_index = c;
      }
    }
    if (worst <= settings.outlier_chi2) return out;
    out.trusted[worst_index] = false;
  }
}

}  // namespace antslam::mapping
