#pragma once
// JSON pieces of the reports of `antslam frontend` and `antslam map` (units in the keys: metres,
// radians, seconds; poses [x, y, theta], covariances 3 x 3 row-major).

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "frontend/frontend.hpp"
#include "frontend/laser_log.hpp"
#include "frontend_options.hpp"
#include "slamgraph/gaussian2.hpp"
#include "slamgraph/pose2.hpp"

namespace antslam::cli {

nlohmann::json pose_json(const slam::Pose2& p);
nlohmann::json covariance_json(const Eigen::Matrix3d& c);
nlohmann::json gaussian_json(const slam::Gaussian2& g);

/// The log (file, scans, beams, skipped messages) and the frontend's settings.
nlohmann::json frontend_input_json(const std::string& log_path, const frontend::LaserLog& log,
                                   const FrontendOptions& options);

/// Per fragment: first scan, scans, length, frame in W, exit, alignment; the accepted closures;
/// every closure candidate matched; scan-matcher statistics.
nlohmann::json frontend_result_json(const frontend::FrontendResult& result);

}  // namespace antslam::cli
