// antslam tinyslam LOG --out-dir DIR: the tinySLAM-style baseline (baselines/) on a
// CARMEN log. Writes DIR/trajectory.tum (a pose for every scan), DIR/map.png (its one map) and
// DIR/report.json (settings, counts, times).

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "antslam/baselines/tinyslam.hpp"
#include "antslam/frontend/image.hpp"
#include "antslam/frontend/laser_log.hpp"
#include "antslam/io/errors.hpp"
#include "antslam/io/json_output.hpp"
#include "antslam/io/output_files.hpp"
#include "antslam/io/progress.hpp"
#include "antslam/slamgraph/trajectory.hpp"
#include "commands.hpp"
#include "output_options.hpp"
#include "sensor_options.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

struct TinySlamOptions {
  std::filesystem::path log;
  std::filesystem::path out;
  baselines::TinySlamSettings settings;
  SensorOptions sensor;
};

void run(const TinySlamOptions& o) {
  baselines::validate(o.settings);
  io::OutputFiles outputs;
  const std::filesystem::path trajectory = outputs.add(o.out / "trajectory.tum");
  const std::filesystem::path map = outputs.add(o.out / "map.png");
  const std::filesystem::path report_path = outputs.add(o.out / "report.json");
  const frontend::LaserLog log = read_laser_log(o.log, o.sensor);
  frontend::require_time_order(log);
  io::Progress progress;
  const auto start = std::chrono::steady_clock::now();
  const baselines::TinySlamResult result = io::in_context_of(o.log, [&] {
    return baselines::run_tinyslam(log, o.settings, [&](std::size_t done) {
      progress.update("tinyslam: scan " + std::to_string(done) + "/" +
                      std::to_string(log.scans.size()));
    });
  });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.clear();

  outputs.write(trajectory, [&](std::ostream& out) { slam::write_tum(out, result.trajectory); });
  outputs.write(map, frontend::encode_png(baselines::map_image(result.map)));
  const baselines::TinySlamSettings& s = o.settings;
  const nlohmann::json report = {
      {"log", o.log.string()},
      {"scans", log.scans.size()},
      {"settings",
       {{"resolution_m", s.resolution},
        {"min_range_m", s.min_range},
        {"max_range_m", s.max_range},
        {"hole_width_m", s.hole_width},
        {"quality", s.quality},
        {"refined_quality", s.refined_quality},
        {"sigma_xy_m", s.sigma_xy},
        {"sigma_theta_rad", s.sigma_theta},
        {"stop", s.stop},
        {"seed", s.seed}}},
      {"evaluations", result.evaluations},
      {"unmatched_scans", result.unmatched},
      {"seconds", seconds},
      {"scans_per_second", static_cast<double>(log.scans.size()) / seconds}};
  outputs.write(report_path, io::json_text(report));
  outputs.commit();
  std::printf("%s: %zu scans in %.2f s (%.0f scans/s, %.0f matches per scan)\n",
              o.log.string().c_str(), log.scans.size(), seconds,
              static_cast<double>(log.scans.size()) / seconds,
              static_cast<double>(result.evaluations) / static_cast<double>(log.scans.size()));
  std::printf("wrote %s, %s, %s\n", trajectory.string().c_str(), map.string().c_str(),
              report_path.string().c_str());
}

}  // namespace

void add_tinyslam_command(CLI::App& app) {
  auto options = std::make_shared<TinySlamOptions>();
  baselines::TinySlamSettings& s = options->settings;
  CLI::App* cmd = app.add_subcommand(
      "tinyslam", "tinySLAM-style baseline on a CARMEN log: trajectory.tum, map.png, report.json");
  cmd->add_option("log", options->log, "CARMEN log (.clf/.log, may be gzipped)")->required();
  add_out_dir_option(*cmd, options->out, "output directory (required)");
  cmd->add_option("--seed", s.seed, "seed of the Monte-Carlo search")
      ->check(non_negative_integer())
      ->capture_default_str();
  cmd->add_option("--resolution", s.resolution, "map cell, metres")
      ->check(finite_in(1e-4, 1e3))
      ->capture_default_str();
  cmd->add_option("--hole-width", s.hole_width, "obstacle blur width, metres")
      ->check(finite_in(0.0, 1e3))
      ->capture_default_str();
  cmd->add_option("--quality", s.quality, "q of eq. (1) at the predicted pose")
      ->check(finite_in(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--refined-quality", s.refined_quality, "q of eq. (1) once the search moved it")
      ->check(finite_in(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--sigma-xy", s.sigma_xy, "std of the position draws, metres")
      ->check(finite_in(0.0, 1e3))
      ->capture_default_str();
  cmd->add_option("--sigma-theta", s.sigma_theta, "std of the heading draws, radians")
      ->check(finite_in(0.0, 1e3))
      ->capture_default_str();
  cmd->add_option("--stop", s.stop, "draws without improvement that end a search")
      ->check(count_in(1, baselines::kMaxStop))
      ->capture_default_str();
  cmd->add_option("--map-max-range", s.max_range, "readings beyond are not used, metres")
      ->check(finite_in(0.0, frontend::kMaxLaserRange))
      ->capture_default_str();
  add_sensor_options(*cmd, options->sensor);
  cmd->callback([options] {
    require_output(!options->out.empty(), "--out-dir");
    run(*options);
  });
}

}  // namespace antslam::cli
