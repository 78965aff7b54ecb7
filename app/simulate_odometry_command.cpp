// antslam simulate-odometry LOG --out-dir DIR: turns a corrected log (pose = odom = the corrected
// pose, data/laser/corrected) into a benchmark with ground truth. The corrected poses become the
// reference (DIR/reference.tum); odometry is derived from them and corrupted with seeded noise
// (frontend/odometry_noise.hpp), and the scans are written with it as a raw-like log
// (DIR/log.clf); DIR/report.json records the settings and how far the odometry drifted.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "antslam/eval/evaluation.hpp"
#include "antslam/frontend/carmen_writer.hpp"
#include "antslam/frontend/laser_log.hpp"
#include "antslam/frontend/odometry_benchmark.hpp"
#include "antslam/io/errors.hpp"
#include "antslam/io/json_output.hpp"
#include "antslam/io/output_files.hpp"
#include "antslam/slamgraph/trajectory.hpp"
#include "commands.hpp"
#include "output_options.hpp"
#include "sensor_options.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

struct SimulateOptions {
  std::filesystem::path log;
  std::filesystem::path out;
  std::uint64_t seed = 1;
  frontend::OdometryNoise noise;
  SensorOptions sensor;
};

void run(const SimulateOptions& o) {
  frontend::validate(o.noise);
  io::OutputFiles outputs;
  const std::filesystem::path log_out = outputs.add(o.out / "log.clf");
  const std::filesystem::path reference = outputs.add(o.out / "reference.tum");
  const std::filesystem::path report_path = outputs.add(o.out / "report.json");
  frontend::LaserLog log = read_laser_log(o.log, o.sensor);
  const frontend::OdometryBenchmark b = io::in_context_of(
      o.log, [&] { return frontend::simulate_odometry(std::move(log), o.noise, o.seed); });

  std::ostringstream noise;
  noise << "linear " << o.noise.linear << " m/m, angular " << o.noise.angular << " rad/rad, drift "
        << o.noise.drift << " rad/m, heading bias " << o.noise.heading_bias << " rad/m";
  const std::vector<std::string> comments = {
      "antslam simulate-odometry: scans of " + o.log.filename().string() +
          " with odometry derived from its corrected poses",
      "seed " + std::to_string(o.seed) + "; noise per step: " + noise.str(),
      "the corrected poses are in reference.tum; ODOM messages were dropped"};
  outputs.write(log_out, [&](std::ostream& out) { frontend::write_carmen(out, b.log, comments); });
  outputs.write(reference, [&](std::ostream& out) { slam::write_tum(out, b.reference); });

  const eval::Evaluation drift =
      io::in_context_of(o.log, [&] { return eval::evaluate(b.odometry, b.reference, {}); });
  const double length = slam::path_length(b.reference);
  const nlohmann::json report = {{"log", o.log.string()},
                                 {"scans", b.log.scans.size()},
                                 {"seed", o.seed},
                                 {"noise",
                                  {{"linear_m_per_m", o.noise.linear},
                                   {"angular_rad_per_rad", o.noise.angular},
                                   {"drift_rad_per_m", o.noise.drift},
                                   {"heading_bias_rad_per_m", o.noise.heading_bias}}},
                                 {"restamped", b.restamped},
                                 {"dropped_odom_messages", b.dropped_odometry},
                                 {"path_length_m", length},
                                 {"odometry_ate_rmse_m", drift.ate.translation_m.rmse},
                                 {"odometry_ate_max_m", drift.ate.translation_m.max}};
  outputs.write(report_path, io::json_text(report));
  outputs.commit();

  if (b.restamped)
    std::printf("%s: scan timestamps do not increase strictly: re-stamped evenly from %.6f s\n",
                o.log.string().c_str(), b.log.scans.front().stamp);
  std::printf(
      "%s: %zu scans, %.1f m; simulated odometry (seed %llu): ATE %.3f m rmse, %.3f m max\n",
      o.log.string().c_str(), b.log.scans.size(), length, static_cast<unsigned long long>(o.seed),
      drift.ate.translation_m.rmse, drift.ate.translation_m.max);
  std::printf("wrote %s, %s, %s\n", log_out.string().c_str(), reference.string().c_str(),
              report_path.string().c_str());
}

}  // namespace

void add_simulate_odometry_command(CLI::App& app) {
  auto options = std::make_shared<SimulateOptions>();
  SimulateOptions& o = *options;
  CLI::App* cmd = app.add_subcommand(
      "simulate-odometry",
      "Benchmark from a corrected log: noisy odometry derived from its poses (log.clf), the "
      "poses as reference (reference.tum), report.json");
  cmd->add_option("log", o.log, "corrected CARMEN log (pose = odom = corrected; may be gzipped)")
      ->required();
  add_out_dir_option(*cmd, o.out, "output directory (required)");
  cmd->add_option("--seed", o.seed, "seed of the odometry noise")
      ->check(non_negative_integer())
      ->capture_default_str();
  cmd->add_option("--linear-noise", o.noise.linear, "std of translation error per metre, m/m")
      ->check(finite_in(-1e3, 1e3))
      ->capture_default_str();
  cmd->add_option("--angular-noise", o.noise.angular,
                  "std of heading error per radian turned, rad/rad")
      ->check(finite_in(-1e3, 1e3))
      ->capture_default_str();
  cmd->add_option("--drift-noise", o.noise.drift, "std of heading error per metre, rad/m")
      ->check(finite_in(-1e3, 1e3))
      ->capture_default_str();
  cmd->add_option("--heading-bias", o.noise.heading_bias,
                  "systematic heading error per metre, rad/m")
      ->check(finite_in(-1e3, 1e3))
      ->capture_default_str();
  add_sensor_options(*cmd, o.sensor);
  cmd->callback([options] {
    require_output(!options->out.empty(), "--out-dir");
    run(*options);
  });
}

}  // namespace antslam::cli
