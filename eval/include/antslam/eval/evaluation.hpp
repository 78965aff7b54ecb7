#pragma once
// Everything `antslam eval` reports, in one call for experiments: association, optional rigid
// alignment, ATE, RPE and, given relations, the Kuemmerle et al. 2009 metric.

#include <cstddef>
#include <optional>
#include <span>

#include "antslam/eval/ate.hpp"
#include "antslam/eval/relations_error.hpp"
#include "antslam/eval/rpe.hpp"
#include "antslam/slamgraph/result_io.hpp"
#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::eval {

struct EvaluationSettings {
  double max_dt = 0.02;             ///< association tolerance between timestamps, seconds
  bool align = true;                ///< rigidly align the estimate onto the reference for ATE
  RpeSettings rpe;                  ///< step of the relative pose error
  double relations_max_dt = 0.001;  ///< tolerance between a relation's stamps and the
                                    ///< estimate's, seconds; relations name scans, so small
};

struct Evaluation {
  EvaluationSettings settings;               ///< the settings used
  std::size_t estimate_poses = 0;            ///< poses in the estimate
  std::size_t reference_poses = 0;           ///< poses in the reference
  std::size_t associated = 0;                ///< associated (estimate, reference) pairs
  AteResult ate;                             ///< absolute trajectory error
  RpeResult rpe;                             ///< relative pose error
  std::optional<RelationsResult> relations;  ///< relations metric, if relations were given
};

/// Throws std::invalid_argument with one line on invalid settings, when no pose can be
/// associated (the message gives both time ranges), and when RPE or relations have nothing to
/// score. An empty `relations` means: no relations metric.
Evaluation evaluate(const slam::Trajectory& estimate, const slam::Trajectory& reference,
                    const EvaluationSettings& settings, std::span<const Relation> relations = {});

/// Poses without timestamps (e.g. fragment frames F_i) against reference poses of the same
/// index, after rigid SE(2) alignment: the absolute trajectory error. Throws
/// std::invalid_argument if the sizes differ or are zero.
slam::TrajectoryError frames_error(std::span<const slam::Pose2> frames,
                                   std::span<const slam::Pose2> reference);

}  // namespace antslam::eval
