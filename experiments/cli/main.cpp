// antslam: the command-line entry point. Errors end the program with one line on stderr and a
// non-zero exit status.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"antslam: ant colony optimization for SLAM map optimization and the TSP"};
  app.require_subcommand(1);
  antslam::cli::add_eval_command(app);
  antslam::cli::add_optimize_command(app);
  antslam::cli::add_synth_command(app);
  antslam::cli::add_g2o_command(app);
  antslam::cli::add_frontend_command(app);
  antslam::cli::add_map_command(app);
  antslam::cli::add_tsp_command(app);
  antslam::cli::add_tsp_experiment_command(app);
  antslam::cli::add_tsp_generate_command(app);
  antslam::cli::add_odometry_command(app);
  antslam::cli::add_simulate_odometry_command(app);
  antslam::cli::add_tinyslam_command(app);
  antslam::cli::add_fragment_set_command(app);
  antslam::cli::add_outliers_command(app);
  antslam::cli::add_robust_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "antslam: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
