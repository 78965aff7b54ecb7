#include "antslam/mapping/optimize_map.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "antslam/slamgraph/trials.hpp"

namespace antslam::mapping {

slam::OptimizeSettings default_mapping_optimizer() {
  slam::OptimizeSettings s;
  s.method = slam::Method::hybrid_nlopt;
  return s;
}

void validate(const MappingSettings& s) {
  if (s.trials < 1) throw std::invalid_argument("mapping: trials must be >= 1");
  slam::validate(s.optimize);
  validate(s.closing);
}

std::vector<ClosureResidual> closure_residuals(const slam::FragmentSet& set,
                                               std::span<const slam::Pose2> frames) {
  std::vector<ClosureResidual> out;
  out.reserve(set.closures.size());
  for (const slam::LoopClosure& c : set.closures) {
    const Eigen::Vector3d r = c.hypothesis.residual(slam::closure_pose(c, frames));
    out.push_back({c.from, c.to, slam::Pose2{r.x(), r.y(), r.z()},
                   std::sqrt(r.dot(c.hypothesis.information() * r))});
  }
  return out;
}

MappingResult optimize_map(const slam::FragmentSet& set, const MappingSettings& settings,
                           const TrialObserver& observer) {
  validate(settings);
  if (set.closures.empty())
    throw std::invalid_argument(set.name +
                                ": the frontend found no loop closure, so there is "
                                "nothing to optimise (the scan-matcher map is the result)");
  const auto start = std::chrono::steady_clock::now();
  MappingResult r;
  r.trials = slam::run_trials(set, settings.optimize,
                              {settings.trials, settings.threads, settings.backend}, observer);
  r.best = slam::best_trial(r.trials);
  const std::vector<slam::Pose2> means = slam::mean_alignments(set);
  r.scan_matcher = slam::score(set, means);
  r.scan_matcher_frames = slam::chain(means);
  r.before = closure_residuals(set, r.scan_matcher_frames);
  r.frames = r.trials[r.best].frames;
  if (settings.closing.enabled) {
    r.closing = close_loops(set, r.frames, settings.closing);
    r.frames = r.closing->frames;
  }
  r.scores = slam::score(set, slam::relative_alignments(r.frames));
  r.after = closure_residuals(set, r.frames);
  r.corrected = slam::world_trajectory(set, r.frames);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace antslam::mapping
