// antslam frontend LOG --out-dir DIR: the laser frontend on a CARMEN log (paper Sec. III-A). Writes
// the scan-matcher trajectory (TUM), the scan-matcher map (PNG, every second fragment tinted as
// in the paper's Fig. 4) and a JSON report of fragments, closures and times.

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "antslam/frontend/image.hpp"
#include "antslam/frontend/laser_log.hpp"
#include "antslam/frontend/map_render.hpp"
#include "antslam/frontend/report.hpp"
#include "antslam/io/errors.hpp"
#include "antslam/io/json_output.hpp"
#include "antslam/io/output_files.hpp"
#include "antslam/io/progress.hpp"
#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/trajectory.hpp"
#include "commands.hpp"
#include "frontend_options.hpp"
#include "output_options.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

using nlohmann::json;
namespace fe = antslam::frontend;

/// Random sample sequences --average-samples may draw: each one renders every scan again.
constexpr std::uint64_t kMaxAverageSamples = 10000;

struct FrontendCommandOptions {
  std::filesystem::path log;
  std::filesystem::path out;
  FrontendOptions frontend;
  std::size_t average_samples = 0;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void run(FrontendCommandOptions c) {
  const auto start = std::chrono::steady_clock::now();
  FrontendOptions& o = c.frontend;
  resolve(o);
  fe::validate(o.map);
  fe::validate(o.settings);
  io::OutputFiles outputs;
  const std::filesystem::path trajectory = outputs.add(c.out / "trajectory.tum");
  const std::filesystem::path map_path = outputs.add(c.out / "map.png");
  const std::filesystem::path samples_path = outputs.add(c.out / "map-samples.png");
  const std::filesystem::path report_path = outputs.add(c.out / "report.json");

  const fe::LaserLog log = read_laser_log(c.log, o.sensor);
  fe::require_time_order(log);
  const double read_seconds = seconds_since(start);
  io::Progress progress;
  const auto matching = std::chrono::steady_clock::now();
  const fe::FrontendResult result =
      io::in_context_of(c.log, [&] { return run_frontend(log, o.settings, progress); });
  const double frontend_seconds = seconds_since(matching);
  progress.update("frontend: drawing the map", true);

  const auto drawing = std::chrono::steady_clock::now();
  const fe::Image map = io::in_context_of(c.log, [&] {
    return fe::render_map(log, fe::map_layout(result), fe::scan_matcher_frames(result), o.map);
  });
  outputs.write(map_path, fe::encode_png(map));
  if (c.average_samples > 0 && result.fragments.size() > 1) {
    progress.update("frontend: averaging maps of random sample sequences", true);
    outputs.write(samples_path, fe::encode_png(io::in_context_of(c.log, [&] {
                    return fe::render_sample_average_map(log, result, c.average_samples,
                                                         o.settings.fragmentation.seed, o.map);
                  })));
  }
  const double map_seconds = seconds_since(drawing);
  progress.clear();

  outputs.write(trajectory, [&](std::ostream& out) { slam::write_tum(out, result.trajectory); });
  const json times = {
      {"read_s", read_seconds},
      {"scan_matching_s", result.stats.matching_seconds},
      {"loop_closure_s", result.stats.closure_seconds},
      {"frontend_s", frontend_seconds},
      {"scans_per_second", static_cast<double>(log.scans.size()) / frontend_seconds},
      {"map_s", map_seconds},
      {"total_s", seconds_since(start)}};
  nlohmann::json report = fe::input_json(c.log.string(), log, o.settings, o.map);
  report.update(fe::result_json(result));
  report["times"] = times;
  outputs.write(report_path, io::json_text(report));
  outputs.commit();

  std::printf(
      "%s: %zu scans in %.2f s (%.0f scans/s), %zu fragments, %zu loop closures (%zu "
      "candidates matched)\n",
      c.log.string().c_str(), log.scans.size(), frontend_seconds,
      static_cast<double>(log.scans.size()) / frontend_seconds, result.fragments.size(),
      result.fragment_set.closures.size(), result.attempts.size());
  std::printf("wrote %s, %s (%zu x %zu), %s\n", trajectory.string().c_str(),
              map_path.string().c_str(), map.width(), map.height(), report_path.string().c_str());
}

}  // namespace

void add_frontend_command(CLI::App& app) {
  auto options = std::make_shared<FrontendCommandOptions>();
  FrontendCommandOptions& o = *options;
  CLI::App* sub =
      app.add_subcommand("frontend",
                         "Scan matching, fragments and loop closures of a CARMEN laser log (paper "
                         "Sec. III-A); writes trajectory.tum, map.png and report.json");
  sub->add_option("log", o.log, "CARMEN log (.clf/.log, may be gzipped)")->required();
  add_out_dir_option(*sub, o.out, "output directory (required)");
  sub->add_option("--seed", o.frontend.settings.fragmentation.seed, "seed of the samples")
      ->check(non_negative_integer())
      ->capture_default_str();
  add_frontend_options(*sub, o.frontend);
  add_map_options(*sub, o.frontend);
  sub->add_option("--average-samples", o.average_samples,
                  "also write map-samples.png: the average map of this many random sample "
                  "sequences (eqs. 7-8)")
      ->check(count_in(0, kMaxAverageSamples));
  sub->callback([options] {
    require_output(!options->out.empty(), "--out-dir");
    run(*options);
  });
}

}  // namespace antslam::cli
