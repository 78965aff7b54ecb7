#pragma once
// Options shared by `antslam optimize` and `antslam map`: the method, the engine's parameters,
// NLopt refinement and Ceres.

#include <CLI/CLI.hpp>

#include <string>

#include "antslam/slamgraph/optimize.hpp"

namespace antslam::cli {

struct OptimizerOptions {
  std::string method = "hybrid";          ///< --method (slam::parse_method)
  std::string nlopt_algorithm = "lbfgs";  ///< --nlopt-algorithm
  bool no_graduated = false;              ///< --no-graduated: plain NLopt refinement only
  std::string backend = "auto";           ///< --backend (aco::kBackends)
  slam::OptimizeSettings settings;        ///< everything else
};

/// Registers --method, --seed, --backend and the engine, NLopt and Ceres options on `command`.
void add_optimizer_options(CLI::App& command, OptimizerOptions& options);

/// The settings with the method and NLopt algorithm parsed from their names; throws
/// std::invalid_argument naming the valid values.
slam::OptimizeSettings optimize_settings(const OptimizerOptions& options);

}  // namespace antslam::cli
