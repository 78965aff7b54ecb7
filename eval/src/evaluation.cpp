#include "antslam/eval/evaluation.hpp"

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "antslam/eval/alignment.hpp"
#include "antslam/eval/association.hpp"

namespace antslam::eval {

namespace {

std::string time_range(const slam::Trajectory& trajectory) {
  if (trajectory.empty()) return "no poses";
  std::ostringstream text;
  text << std::fixed;
  text.precision(6);
  text << trajectory.size() << " poses, " << trajectory.front().stamp << " .. "
       << trajectory.back().stamp << " s";
  return text.str();
}

}  // namespace

Evaluation evaluate(const slam::Trajectory& estimate, const slam::Trajectory& reference,
                    const EvaluationSettings& settings, std::span<const Relation> relations) {
  const std::vector<PosePair> pairs = associate(estimate, reference, settings.max_dt);
  if (pairs.empty()) {
    std::ostringstream message;
    message << "no estimated pose has a reference pose within max_dt = " << settings.max_dt
            << " s (estimate: " << time_range(estimate) << "; reference: " << time_range(reference)
            << ")";
    throw std::invalid_argument(message.str());
  }
  Evaluation result;
  result.settings = settings;
  result.estimate_poses = estimate.size();
  result.reference_poses = reference.size();
  result.associated = pairs.size();
  result.ate = ate(pairs, settings.align ? align(pairs) : slam::Pose2{});
  result.rpe = rpe(pairs, settings.rpe);
  if (!relations.empty())
    result.relations = relations_error(estimate, relations, settings.relations_max_dt);
  return result;
}

slam::TrajectoryError frames_error(std::span<const slam::Pose2> frames,
                                   std::span<const slam::Pose2> reference) {
  const AteResult e = indexed_ate(frames, reference);
  return {e.translation_m.rmse, e.translation_m.max, e.rotation_deg.rmse, frames.size()};
}

}  // namespace antslam::eval
