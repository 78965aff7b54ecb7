#pragma once
// Options shared by `antslam frontend`, `antslam map` and `antslam fragment-set`: sensor
// geometry, scan matching, fragments, loop closing and the map cell size.

#include <CLI/CLI.hpp>

#include <string>

#include "antslam/frontend/frontend.hpp"
#include "antslam/frontend/laser_log.hpp"
#include "antslam/frontend/map_render.hpp"
#include "antslam/io/progress.hpp"
#include "sensor_options.hpp"

namespace antslam::cli {

struct FrontendOptions {
  frontend::FrontendSettings settings;    ///< scan matcher, fragments, closures
  SensorOptions sensor;                   ///< --fov, --first-beam, --max-range, --laser-offset
  std::string alignment = "accumulated";  ///< --alignment: accumulated or exit-scan
  bool no_closures = false;               ///< --no-closures
  frontend::MapRenderSettings map;        ///< --resolution
};

/// Registers the options on `command` (not --seed: each command seeds its own way).
void add_frontend_options(CLI::App& command, FrontendOptions& options);

/// Registers --resolution, for the commands that draw maps.
void add_map_options(CLI::App& command, FrontendOptions& options);

/// Turns the name options into settings (call once, after parsing).
void resolve(FrontendOptions& options);

/// Runs the frontend over the log, showing the scan count, fragments and closures on
/// `progress`.
frontend::FrontendResult run_frontend(const frontend::LaserLog& log,
                                      const frontend::FrontendSettings& settings,
                                      io::Progress& progress);

}  // namespace antslam::cli
