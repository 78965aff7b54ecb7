#pragma once
// The AntSLAM pipeline in one call (paper Secs. III-IV): a CARMEN laser log -> the frontend's
// fragment set (scan matching, fragments with the Gaussians of eqs. (5)-(6) and samples of
// eq. (7), loop closures) -> the optimizer (eq. (10); several trials, the lowest weight wins)
// -> the corrected pose of every scan, the maps of Fig. 5 and, given a reference, the error of
// both trajectories against it.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "antslam/eval/evaluation.hpp"
#include "antslam/frontend/frontend.hpp"
#include "antslam/frontend/image.hpp"
#include "antslam/frontend/laser_log.hpp"
#include "antslam/frontend/map_render.hpp"
#include "antslam/mapping/optimize_map.hpp"
#include "antslam/mapping/verdict.hpp"
#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::mapping {

struct PipelineSettings {
  frontend::SensorOverrides sensor;     ///< laser geometry that wins over the log's PARAM lines
  frontend::FrontendSettings frontend;  ///< scan matcher, fragments, loop closures
  MappingSettings mapping;              ///< optimizer, trials, threads
  frontend::MapRenderSettings map;      ///< cell size of the maps
  bool draw_maps = true;                ///< render the three maps
};

/// Throws std::invalid_argument naming the first nonsensical field.
void validate(const PipelineSettings& settings);

/// The maps of a run: the scan matcher's (Fig. 5a, every second fragment tinted), the best
/// trial's, and the average over all trials (Fig. 5b).
struct PipelineMaps {
  frontend::Image scan_matcher;
  frontend::Image optimized;
  frontend::Image average;
  double resolution = 0.0;  ///< metres per pixel: the settings' unless too many pixels for
                            ///< max_pixels, then the finest that fits (a warning says so)
};

/// Scan-matcher and optimized trajectories against a reference (antslam eval's figures).
struct MapEvaluation {
  std::string reference;          ///< where the reference came from (file)
  eval::Evaluation scan_matcher;  ///< the frontend's trajectory
  eval::Evaluation optimized;     ///< the corrected trajectory
};

struct PipelineTimes {
  double read_s = 0.0;          ///< reading the log (0 when given in memory)
  double frontend_s = 0.0;      ///< scan matching, fragments and loop closures
  double optimization_s = 0.0;  ///< all trials
  double maps_s = 0.0;          ///< rendering the maps
  double total_s = 0.0;         ///< the whole call
};

struct PipelineResult {
  frontend::LaserLog log;                   ///< the log as read (geometry applied)
  frontend::FrontendResult frontend;        ///< fragment set, scan-matcher trajectory, closures
  MappingResult mapping;                    ///< the trials and the corrected trajectory
  std::optional<PipelineMaps> maps;         ///< when settings.draw_maps and they could be drawn
  std::optional<MapEvaluation> evaluation;  ///< when a reference was given
  std::vector<std::string> warnings;        ///< the log's (sensor_check.hpp), the maps'
  Verdict verdict;                          ///< is the map doubtful (verdict.hpp)
  PipelineTimes times;
};

/// A stage of the pipeline, for progress lines: `final` marks the last report of a stage.
using StageObserver = std::function<void(std::string_view stage, bool final)>;

/// Reference for the evaluation, by file (read and checked before any work) or in memory.
struct Reference {
  std::string name;             ///< for the report (the file)
  slam::Trajectory trajectory;  ///< TUM poses
};

/// Runs the pipeline on a log held in memory (its `source` names the fragment set). Throws
/// std::invalid_argument for invalid settings and when the frontend finds no loop closure
/// (nothing to optimise); a map that cannot be drawn is a warning, never an error.
PipelineResult run_pipeline(frontend::LaserLog log, const PipelineSettings& settings,
                            const std::optional<Reference>& reference = std::nullopt,
                            const StageObserver& observer = {});

/// Reads the log (and the reference TUM file, if not empty) and runs the pipeline. Settings and
/// the reference are checked before the log is read.
PipelineResult run_pipeline(const std::filesystem::path& log, const PipelineSettings& settings,
                            const std::filesystem::path& reference = {},
                            const StageObserver& observer = {});

}  // namespace antslam::mapping
