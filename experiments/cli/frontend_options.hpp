#pragma once
// Options shared by `antslam frontend` and `antslam map`: sensor geometry, scan matching,
// fragments, loop closing and the map cell size.

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "cli/progress.hpp"
#include "frontend/frontend.hpp"
#include "frontend/laser_log.hpp"
#include "frontend/map_render.hpp"

namespace antslam::cli {

struct FrontendOptions {
  frontend::FrontendSettings settings;       ///< scan matcher, fragments, closures
  frontend::SensorOverrides sensor;          ///< geometry overrides (radians, metres)
  std::optional<double> fov_degrees;         ///< --fov, degrees
  std::optional<double> first_beam_degrees;  ///< --first-beam, degrees
  std::string alignment = "accumulated";     ///< --alignment: accumulated or exit-scan
  bool no_closures = false;                  ///< --no-closures
  frontend::MapRenderSettings map;           ///< --resolution
};

/// Registers the options on `command` (not --seed: each command seeds its own way).
void add_frontend_options(CLI::App& command, FrontendOptions& options);

/// Turns the degree and name options into settings (call once, after parsing).
void resolve(FrontendOptions& options);

/// Runs the frontend over the log, showing the scan count, fragments and closures on
/// `progress`. `name` goes into the fragment set.
frontend::FrontendResult run_frontend(const frontend::LaserLog& log,
                                      const frontend::FrontendSettings& settings,
                                      const std::string& name, Progress& progress);

}  // namespace antslam::cli
