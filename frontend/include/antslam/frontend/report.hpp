#pragma once
// JSON pieces of the frontend's report (units in the keys: metres, radians, seconds; poses
// [x, y, theta], covariances 3 x 3 row-major), shared by `antslam frontend` and the mapping
// pipeline's report.

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "antslam/frontend/frontend.hpp"
#include "antslam/frontend/laser_log.hpp"
#include "antslam/frontend/map_render.hpp"
#include "antslam/slamgraph/gaussian2.hpp"
#include "antslam/slamgraph/pose2.hpp"

namespace antslam::frontend {

nlohmann::json pose_json(const slam::Pose2& p);
nlohmann::json covariance_json(const Eigen::Matrix3d& c);
nlohmann::json gaussian_json(const slam::Gaussian2& g);

/// "accumulated" or "exit-scan" (the names of the --alignment option).
std::string_view to_string(AlignmentCovariance covariance);
/// The inverse of to_string; throws std::invalid_argument naming the unknown name.
AlignmentCovariance parse_alignment_covariance(std::string_view name);

/// The log (file, scans, beams, skipped messages), the frontend's settings and the map cell size.
nlohmann::json input_json(const std::string& log_path, const LaserLog& log,
                          const FrontendSettings& settings, const MapRenderSettings& map);

/// Per fragment: first scan, scans, length, frame in W, exit, alignment; the accepted closures;
/// every closure candidate matched; scan-matcher statistics.
nlohmann::json result_json(const FrontendResult& result);

}  // namespace antslam::frontend
