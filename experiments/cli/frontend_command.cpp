// antslam frontend LOG --out DIR: the laser frontend on a CARMEN log (paper Sec. III-A). Writes
// the scan-matcher trajectory (TUM), the scan-matcher map (PNG, every second fragment tinted as
// in the paper's Fig. 4) and a JSON report of fragments, closures and times.

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "aco/random.hpp"
#include "cli/atomic_file.hpp"
#include "cli/progress.hpp"
#include "commands.hpp"
#include "frontend/frontend.hpp"
#include "frontend/image.hpp"
#include "frontend/laser_log.hpp"
#include "frontend/map_render.hpp"
#include "slamgraph/fragment_set.hpp"
#include "slamgraph/trajectory.hpp"

namespace antslam::cli {

namespace {

using nlohmann::json;
namespace fe = antslam::frontend;

struct FrontendOptions {
  std::filesystem::path log;
  std::filesystem::path out;
  fe::FrontendSettings settings;
  fe::SensorOverrides sensor;
  std::optional<double> fov_degrees, first_beam_degrees;
  std::string alignment = "accumulated";
  bool no_closures = false;
  std::size_t average_samples = 0;
  fe::MapRenderSettings map;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

json pose_json(const slam::Pose2& p) { return json::array({p.x, p.y, p.theta}); }

json covariance_json(const Eigen::Matrix3d& c) {
  json rows = json::array();
  for (int r = 0; r < 3; ++r) rows.push_back(json::array({c(r, 0), c(r, 1), c(r, 2)}));
  return rows;
}

json gaussian_json(const slam::Gaussian2& g) {
  return {{"mean", pose_json(g.mean())}, {"covariance", covariance_json(g.covariance())}};
}

json report_json(const FrontendOptions& o, const fe::LaserLog& log, const fe::FrontendResult& r,
                 const json& times) {
  json fragments = json::array();
  for (std::size_t i = 0; i < r.fragments.size(); ++i) {
    const fe::FragmentRecord& f = r.fragments[i];
    const slam::Fragment& s = r.fragment_set.fragments[i];
    json entry = {{"index", i},
                  {"first_scan", f.first_scan},
                  {"scans", f.scan_count},
                  {"length_m", f.length},
                  {"frame", pose_json(f.frame)},
                  {"exit", pose_json(s.exit)},
                  {"samples", s.samples.size()}};
    if (s.alignment) entry["alignment"] = gaussian_json(*s.alignment);
    fragments.push_back(entry);
  }
  json closures = json::array();
  for (const slam::LoopClosure& c : r.fragment_set.closures)
    closures.push_back({{"from", c.from},
                        {"to", c.to},
                        {"anchor", pose_json(c.anchor)},
                        {"hypothesis", gaussian_json(c.hypothesis)}});
  json attempts = json::array();
  for (const fe::ClosureAttempt& a : r.attempts)
    attempts.push_back({{"from", a.from},
                        {"to", a.to},
                        {"ellipse_mahalanobis2", a.mahalanobis},
                        {"prior", pose_json(a.prior)},
                        {"prior_covariance", covariance_json(a.prior_covariance)},
                        {"found", pose_json(a.match.pose)},
                        {"score", a.match.score},
                        {"second_score", a.match.second_score},
                        {"accepted", a.match.accepted},
                        {"reason", a.match.reason},
                        {"seconds", a.seconds}});
  const fe::FrontendSettings& s = o.settings;
  return {
      {"log", o.log.string()},
      {"scans", log.scans.size()},
      {"beams", log.scans.front().ranges.size()},
      {"skipped_messages", log.skipped_messages},
      {"settings",
       {{"fragment_length_m", s.fragmentation.length},
        {"samples", s.fragmentation.samples},
        {"seed", s.fragmentation.seed},
        {"alignment", o.alignment},
        {"covariance_scale", s.fragmentation.covariance_scale},
        {"temperature", s.matcher.temperature},
        {"closures", s.closure.enabled},
        {"closure_min_score", s.closure.min_score},
        {"closure_max_second_ratio", s.closure.max_second_ratio},
        {"map_resolution_m", o.map.resolution}}},
      {"stats", {{"unmatched_scans", r.stats.unmatched}, {"recovered_scans", r.stats.recovered}}},
      {"fragments", fragments},
      {"closures", closures},
      {"closure_attempts", attempts},
      {"times", times}};
}

/// The average map over `count` random sample sequences (one sample of eq. (7) per fragment,
/// placed by eq. (8)): the spread of maps the optimizer chooses from, drawn like Fig. 5b.
fe::Image sample_average(const fe::LaserLog& log, const fe::FrontendResult& r, std::size_t count,
                         std::uint64_t seed, const fe::MapRenderSettings& settings) {
  const slam::FragmentSet& set = r.fragment_set;
  const std::size_t samples = set.fragments.size() > 1 ? set.fragments[1].samples.size() : 0;
  std::vector<std::vector<slam::Pose2>> trials;
  aco::Rng rng(aco::mix_seed(seed, 0xA7E5));
  for (std::size_t t = 0; t < count; ++t) {
    std::vector<std::uint32_t> choice(set.layer_count());
    for (std::uint32_t& c : choice) c = rng.below(static_cast<std::uint32_t>(samples));
    trials.push_back(slam::world_frames(set, choice));
  }
  return fe::render_average_map(log, fe::map_layout(r), trials, settings);
}

void run(FrontendOptions o) {
  const auto start = std::chrono::steady_clock::now();
  if (o.fov_degrees) o.sensor.field_of_view = *o.fov_degrees * std::numbers::pi / 180.0;
  if (o.first_beam_degrees) o.sensor.first_angle = *o.first_beam_degrees * std::numbers::pi / 180.0;
  if (o.alignment == "exit-scan")
    o.settings.fragmentation.covariance = fe::AlignmentCovariance::exit_scan;
  o.settings.closure.enabled = !o.no_closures;
  fe::validate(o.map);
  fe::Frontend frontend(o.settings, o.log.filename().string());  // validates the settings

  const fe::LaserLog log = fe::read_carmen_file(o.log, o.sensor);
  const double read_seconds = seconds_since(start);
  Progress progress;
  const auto matching = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    frontend.add_scan(log.scans[i]);
    progress.update("frontend: scan " + std::to_string(i + 1) + "/" +
                    std::to_string(log.scans.size()) + ", fragments " +
                    std::to_string(frontend.fragment_count()) + ", closures " +
                    std::to_string(frontend.closure_count()));
  }
  const fe::FrontendResult result = frontend.finish();
  const double frontend_seconds = seconds_since(matching);
  progress.update("frontend: drawing the map", true);

  const auto drawing = std::chrono::steady_clock::now();
  const fe::Image map =
      fe::render_map(log, fe::map_layout(result), fe::scan_matcher_frames(result), o.map);
  const std::string png = fe::encode_png(map);
  std::string average_png;
  if (o.average_samples > 0 && result.fragments.size() > 1) {
    progress.update("frontend: averaging maps of random sample sequences", true);
    average_png = fe::encode_png(
        sample_average(log, result, o.average_samples, o.settings.fragmentation.seed, o.map));
  }
  const double map_seconds = seconds_since(drawing);
  progress.clear();

  write_atomically(o.out / "trajectory.tum",
                   [&](std::ostream& out) { slam::write_tum(out, result.trajectory); });
  write_atomically(o.out / "map.png", png);
  if (!average_png.empty()) write_atomically(o.out / "map-samples.png", average_png);
  const json times = {
      {"read_s", read_seconds},
      {"scan_matching_s", result.stats.matching_seconds},
      {"loop_closure_s", result.stats.closure_seconds},
      {"frontend_s", frontend_seconds},
      {"scans_per_second", static_cast<double>(log.scans.size()) / frontend_seconds},
      {"map_s", map_seconds},
      {"total_s", seconds_since(start)}};
  write_atomically(o.out / "report.json", [&](std::ostream& out) {
    out << report_json(o, log, result, times).dump(2) << '\n';
  });

  std::printf(
      "%s: %zu scans in %.2f s (%.0f scans/s), %zu fragments, %zu loop closures (%zu "
      "candidates matched)\n",
      o.log.string().c_str(), log.scans.size(), frontend_seconds,
      static_cast<double>(log.scans.size()) / frontend_seconds, result.fragments.size(),
      result.fragment_set.closures.size(), result.attempts.size());
  std::printf("wrote %s, %s (%zu x %zu), %s\n", (o.out / "trajectory.tum").string().c_str(),
              (o.out / "map.png").string().c_str(), map.width(), map.height(),
              (o.out / "report.json").string().c_str());
}

}  // namespace

void add_frontend_command(CLI::App& app) {
  auto options = std::make_shared<FrontendOptions>();
  FrontendOptions& o = *options;
  CLI::App* sub =
      app.add_subcommand("frontend",
                         "Scan matching, fragments and loop closures of a CARMEN laser log (paper "
                         "Sec. III-A); writes trajectory.tum, map.png and report.json");
  sub->add_option("log", o.log, "CARMEN log (.clf/.log, may be gzipped)")->required();
  sub->add_option("--out", o.out, "output directory")->required();
  sub->add_option("--fragment-length", o.settings.fragmentation.length,
                  "metres travelled per fragment")
      ->capture_default_str();
  sub->add_option("--samples", o.settings.fragmentation.samples,
                  "samples M per fragment alignment (eq. 7)")
      ->capture_default_str();
  sub->add_option("--seed", o.settings.fragmentation.seed, "seed of the samples")
      ->capture_default_str();
  sub->add_option("--alignment", o.alignment,
                  "alignment covariance: accumulated (eqs. 5-6 of every scan, composed) or "
                  "exit-scan (the paper: eqs. 5-6 of the exit scan)")
      ->check(CLI::IsMember({"accumulated", "exit-scan"}))
      ->capture_default_str();
  sub->add_option("--covariance-scale", o.settings.fragmentation.covariance_scale,
                  "multiplies the alignment covariance")
      ->capture_default_str();
  sub->add_option("--temperature", o.settings.matcher.temperature,
                  "scan-matcher likelihood temperature")
      ->capture_default_str();
  sub->add_option("--fov", o.fov_degrees, "laser field of view, degrees (overrides the log)");
  sub->add_option("--first-beam", o.first_beam_degrees,
                  "angle of the first beam, degrees (default -fov/2; overrides the log)");
  sub->add_option("--max-range", o.sensor.max_range,
                  "laser maximum range, metres: readings at or above are no-returns");
  sub->add_option("--laser-offset", o.sensor.laser_offset,
                  "laser position ahead of the robot origin, metres (overrides the log)");
  sub->add_flag("--no-closures", o.no_closures, "do not look for loop closures");
  sub->add_option("--closure-min-score", o.settings.closure.min_score,
                  "mean point likelihood a loop closure needs, in (0, 1]")
      ->capture_default_str();
  sub->add_option("--closure-max-second", o.settings.closure.max_second_ratio,
                  "reject a closure if a separate peak scores this share of the best")
      ->capture_default_str();
  sub->add_option("--resolution", o.map.resolution, "map cell size, metres")->capture_default_str();
  sub->add_option("--average-samples", o.average_samples,
                  "also write map-samples.png: the average map of this many random sample "
                  "sequences (eqs. 7-8)");
  sub->callback([options] { run(*options); });
}

}  // namespace antslam::cli
