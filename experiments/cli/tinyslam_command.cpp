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

#include "baselines/tinyslam.hpp"
#include "cli/atomic_file.hpp"
#include "cli/progress.hpp"
#include "commands.hpp"
#include "frontend/image.hpp"
#include "frontend/laser_log.hpp"
#include "output_options.hpp"
#include "sensor_options.hpp"
#include "slamgraph/trajectory.hpp"

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
  const frontend::LaserLog log = frontend::read_carmen_file(o.log, o.sensor.overrides());
  Progress progress;
  const auto start = std::chrono::steady_clock::now();
  const baselines::TinySlamResult result =
      baselines::run_tinyslam(log, o.settings, [&](std::size_t done) {
        progress.update("tinyslam: scan " + std::to_string(done) + "/" +
                        std::to_string(log.scans.size()));
      });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.clear();

  write_atomically(o.out / "trajectory.tum",
                   [&](std::ostream& out) { slam::write_tum(out, result.trajectory); });
  write_atomically(o.out / "map.png", frontend::encode_png(baselines::map_image(result.map)));
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
  write_atomically(o.out / "report.json",
                   [&](std::ostream& out) { out << report.dump(2) << '\n'; });
  std::printf("%s: %zu scans in %.2f s (%.0f scans/s, %.0f matches per scan)\n",
              o.log.string().c_str(), log.scans.size(), seconds,
              static_cast<double>(log.scans.size()) / seconds,
              static_cast<double>(result.evaluations) / static_cast<double>(log.scans.size()));
  std::printf("wrote %s, %s, %s\n", (o.out / "trajectory.tum").string().c_str(),
              (o.out / "map.png").string().c_str(), (o.out / "report.json").string().c_str());
}

}  // namespace

void add_tinyslam_command(CLI::App& app) {
  auto options = std::make_shared<TinySlamOptions>();
  baselines::TinySlamSettings& s = options->settings;
  CLI::App* cmd = app.add_subcommand(
      "tinyslam", "tinySLAM-style baseline on a CARMEN log: trajectory.tum, map.png, report.json");
  cmd->add_option("log", options->log, "CARMEN log (.clf/.log, may be gzipped)")->required();
  add_out_dir_option(*cmd, options->out, "output directory (required)");
  cmd->add_option("--seed", s.seed, "seed of the Monte-Carlo search")->capture_default_str();
  cmd->add_option("--resolution", s.resolution, "map cell, metres")->capture_default_str();
  cmd->add_option("--hole-width", s.hole_width, "obstacle blur width, metres")
      ->capture_default_str();
  cmd->add_option("--quality", s.quality, "q of eq. (1) at the predicted pose")
      ->capture_default_str();
  cmd->add_option("--refined-quality", s.refined_quality, "q of eq. (1) once the search moved it")
      ->capture_default_str();
  cmd->add_option("--sigma-xy", s.sigma_xy, "std of the position draws, metres")
      ->capture_default_str();
  cmd->add_option("--sigma-theta", s.sigma_theta, "std of the heading draws, radians")
      ->capture_default_str();
  cmd->add_option("--stop", s.stop, "draws without improvement that end a search")
      ->capture_default_str();
  cmd->add_option("--map-max-range", s.max_range, "readings beyond are not used, metres")
      ->capture_default_str();
  add_sensor_options(*cmd, options->sensor);
  cmd->callback([options] {
    require_output(!options->out.empty(), "--out-dir");
    run(*options);
  });
}

}  // namespace antslam::cli
