#include "commands.hpp"

#include <string>
#include <utility>

#include "antslam/slamgraph/ceres_baseline.hpp"

namespace antslam::cli {

namespace {

/// One example command line per command, on the data the project ships, run from the
/// repository (shown under its help, unwrapped: at most 98 characters).
const std::pair<const char*, const char*> kExamples[] = {
    {"map",
     "antslam map data/laser/malaga-oneloop.clf --laser-offset 0.78 --out-dir results/malaga"},
    {"frontend",
     "antslam frontend data/laser/malaga-oneloop.clf --laser-offset 0.78 --out-dir results/fe"},
    {"fragment-set", "antslam fragment-set data/laser/malaga-oneloop.clf -o results/malaga.json"},
    {"optimize",
     "antslam optimize data/fragment-sets/paper15.json --method hybrid+nlopt --trials 20 -o p15"},
    {"synth", "antslam synth --preset paper15 -o results/paper15.json"},
    {"g2o", "antslam g2o data/posegraphs/ring.g2o -o results/ring.json"},
    {"outliers", "antslam outliers data/posegraphs/ring.g2o --count 100 --kind random -o r100.g2o"},
    {"robust",
     "antslam robust r100.g2o --method pcm-aco --reference data/posegraphs/ring.gt.g2o -o r100"},
    {"eval",
     "antslam eval results/malaga/trajectory.tum results/malaga/trajectory-scan-matcher.tum"},
    {"tsp",
     "antslam tsp --instance data/tsplib/kroA100.tsp --time 10 --tour-out results/kroA100.tour"},
    {"tsp-experiment",
     "antslam tsp-experiment --data-dir data/tsplib --instances eil51,kroA100 --time 1 --csv "
     "runs.csv"},
    {"tsp-generate", "antslam tsp-generate --cities 1000 --seed 1 -o results/random1000.tsp"},
    {"qap", "antslam qap --instance data/qaplib/chr12a.dat --iterations 500 --json chr12a.json"},
    {"odometry", "antslam odometry data/laser/mit-csail.clf -o results/mit-odometry.tum"},
    {"simulate-odometry",
     "antslam simulate-odometry data/laser/corrected/aces-corrected.log.gz --out-dir results/aces"},
    {"tinyslam", "antslam tinyslam data/laser/malaga-oneloop.clf --out-dir results/tinyslam"},
    {"batch", "mpirun -np 2 antslam batch jobs.txt"},
};

}  // namespace

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
  add_qap_command(app);
  add_odometry_command(app);
  add_simulate_odometry_command(app);
  add_tinyslam_command(app);
  add_fragment_set_command(app);
  add_outliers_command(app);
  add_robust_command(app);
  add_batch_command(app);
  for (const auto& [name, example] : kExamples)
    app.get_subcommand(name)->footer(std::string("Example:\n  ") + example);
}

}  // namespace antslam::cli
