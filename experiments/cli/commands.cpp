#include "commands.hpp"

#include "slamgraph/ceres_baseline.hpp"

namespace antslam::cli {

void add_commands(CLI::App& app) {
  app.require_subcommand(1);
  app.fallthrough();  // --verbose may follow the subcommand
  slam::show_solver_logs(false);
  app.add_flag_callback(
         "-v,--verbose", [] { slam::show_solver_logs(true); },
         "also show the solvers' own log messages (Ceres' warnings and diagnostics)")
      ->trigger_on_parse();
  add_eval_command(app);
  add_optimize_command(app);
  add_synth_command(app);
  add_g2o_command(app);
  add_frontend_command(app);
  add_map_command(app);
  add_tsp_command(app);
  add_tsp_experiment_command(app);
  add_tsp_generate_command(app);
  add_odometry_command(app);
  add_simulate_odometry_command(app);
  add_tinyslam_command(app);
  add_fragment_set_command(app);
  add_outliers_command(app);
  add_robust_command(app);
  add_batch_command(app);
}

}  // namespace antslam::cli
