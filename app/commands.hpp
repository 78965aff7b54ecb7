#pragma once
// Every subcommand of the antslam program registers itself on the root CLI::App.

#include <CLI/CLI.hpp>

namespace antslam::cli {

/// The whole program: every subcommand below and the global --verbose flag.
void add_commands(CLI::App& app);

// void add_<name>_command(CLI::App& app);  -- one per subcommand, defined in <name>_command.cpp
void add_eval_command(CLI::App& app);
void add_optimize_command(CLI::App& app);
void add_synth_command(CLI::App& app);
void add_g2o_command(CLI::App& app);
void add_frontend_command(CLI::App& app);
void add_map_command(CLI::App& app);
void add_tsp_command(CLI::App& app);
void add_tsp_experiment_command(CLI::App& app);
void add_tsp_generate_command(CLI::App& app);
void add_qap_command(CLI::App& app);
void add_odometry_command(CLI::App& app);
void add_simulate_odometry_command(CLI::App& app);
void add_tinyslam_command(CLI::App& app);
void add_fragment_set_command(CLI::App& app);
void add_outliers_command(CLI::App& app);
void add_robust_command(CLI::App& app);
void add_batch_command(CLI::App& app);

}  // namespace antslam::cli
