// antslam map LOG --out DIR: the whole AntSLAM pipeline on a CARMEN laser log (paper Secs. III-IV,
// issue 4 item 6). The frontend builds the fragment set, the optimizer (hybrid + NLopt by
// default) places the fragments in several trials, and the lowest-weight trial is the map.
// Writes the fragment set, the corrected and the scan-matcher trajectories (TUM, every scan),
// the scan-matcher map (Fig. 5a), the optimized map, the average map of the trials (Fig. 5b) and
// a JSON report; prints every closure's Mahalanobis distance before and after.

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "cli/atomic_file.hpp"
#include "cli/progress.hpp"
#include "commands.hpp"
#include "frontend/map_render.hpp"
#include "frontend_options.hpp"
#include "frontend_report.hpp"
#include "map_report.hpp"
#include "mapping/optimize_map.hpp"
#include "optimizer_options.hpp"
#include "slamgraph/fragment_set_io.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

namespace fe = antslam::frontend;

struct MapOptions {
  std::filesystem::path log, out, reference;
  FrontendOptions frontend;
  OptimizerOptions optimizer;  ///< --method defaults to hybrid+nlopt (add_map_command)
  mapping::MappingSettings mapping;
  bool no_maps = false;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The three maps (Fig. 5a, the optimized map, Fig. 5b), written to DIR; returns the paths.
std::vector<std::filesystem::path> write_maps(const MapOptions& o, const fe::LaserLog& log,
                                              const fe::FrontendResult& fr,
                                              const mapping::MappingResult& mr,
                                              Progress& progress) {
  const fe::MapLayout layout = fe::map_layout(fr);
  const std::vector<std::filesystem::path> paths{
      o.out / "map-scan-matcher.png", o.out / "map-optimized.png", o.out / "map-average.png"};
  progress.update("maps: scan matcher", true);
  write_atomically(paths[0], fe::encode_png(fe::render_map(log, layout, mr.scan_matcher_frames,
                                                           o.frontend.map)));
  progress.update("maps: optimized", true);
  write_atomically(paths[1], fe::encode_png(fe::render_map(log, layout, mr.trials[mr.best].frames,
                                                           o.frontend.map)));
  progress.update("maps: average of " + std::to_string(mr.trials.size()) + " trials", true);
  std::vector<std::vector<slam::Pose2>> placements;
  for (const slam::OptimizeResult& t : mr.trials) placements.push_back(t.frames);
  write_atomically(paths[2],
                   fe::encode_png(fe::render_average_map(log, layout, placements, o.frontend.map)));
  return paths;
}

std::optional<MapEvaluation> evaluate(const MapOptions& o, const fe::FrontendResult& fr,
                                      const mapping::MappingResult& mr) {
  if (o.reference.empty()) return std::nullopt;
  const slam::Trajectory reference = slam::read_tum_file(o.reference);
  return MapEvaluation{o.reference.string(), eval::evaluate(fr.trajectory, reference, {}),
                       eval::evaluate(mr.corrected, reference, {})};
}

void print_summary(const MapOptions& o, const fe::FrontendResult& fr,
                   const mapping::MappingResult& mr, const std::optional<MapEvaluation>& e) {
  const slam::FragmentSet& set = fr.fragment_set;
  const slam::OptimizeResult& best = mr.trials[mr.best];
  std::printf("%s: %zu scans, %zu fragments, %zu loop closures (frontend %.2f s)\n",
              o.log.string().c_str(), fr.trajectory.size(), set.fragments.size(),
              set.closures.size(), fr.stats.matching_seconds + fr.stats.closure_seconds);
  std::printf("%s, %zu trials (%.2f s): weight (eq. 10) %.4f -> %.4f, chi2 %.6g -> %.6g\n",
              o.optimizer.method.c_str(), mr.trials.size(), mr.seconds, mr.scan_matcher.weight,
              best.scores.weight, mr.scan_matcher.chi2, best.scores.chi2);
  std::size_t within = 0;
  std::printf("loop closures (Mahalanobis distance of the residual, scan matcher -> optimized):\n");
  for (std::size_t c = 0; c < mr.after.size(); ++c) {
    const bool ok = mr.after[c].mahalanobis <= kClosureSigmas;
    within += ok ? 1 : 0;
    std::printf("  %3zu-%-3zu %9.2f -> %6.2f  %s\n", mr.after[c].from, mr.after[c].to,
                mr.before[c].mahalanobis, mr.after[c].mahalanobis,
                ok ? "within 2 sigma" : "OUTSIDE 2 sigma");
  }
  std::printf("  %zu of %zu closures within their 2-sigma ellipse\n", within, mr.after.size());
  if (e)
    std::printf("ATE RMSE vs %s: scan matcher %.4f m, optimized %.4f m (%zu poses)\n",
                e->reference.c_str(), e->scan_matcher.ate.translation_m.rmse,
                e->optimized.ate.translation_m.rmse, e->optimized.associated);
}

void run(MapOptions o) {
  const auto start = std::chrono::steady_clock::now();
  resolve(o.frontend);
  o.mapping.optimize = optimize_settings(o.optimizer);
  o.mapping.backend = o.mapping.optimize.backend;
  o.frontend.settings.fragmentation.seed = o.mapping.optimize.seed;
  fe::validate(o.frontend.settings);
  fe::validate(o.frontend.map);
  mapping::validate(o.mapping);
  if (!o.reference.empty() && !std::filesystem::is_regular_file(o.reference))
    throw std::runtime_error(o.reference.string() + ": cannot open the reference trajectory");

  Progress progress;
  progress.update("reading " + o.log.string(), true);
  const fe::LaserLog log = fe::read_carmen_file(o.log, o.frontend.sensor.overrides());
  const double read_s = seconds_since(start);
  const auto frontend_start = std::chrono::steady_clock::now();
  const fe::FrontendResult fr =
      run_frontend(log, o.frontend.settings, o.log.filename().string(), progress);
  const double frontend_s = seconds_since(frontend_start);
  const slam::FragmentSet& set = fr.fragment_set;
  if (set.closures.empty())
    throw std::runtime_error(o.log.string() + ": the frontend found no loop closure in " +
                             std::to_string(set.fragments.size()) +
                             " fragments, so there is nothing to optimise (antslam frontend "
                             "draws the scan-matcher map)");
  write_atomically(o.out / "fragment-set.json",
                   [&](std::ostream& out) { slam::write_fragment_set(out, set); });

  const std::string trials = std::to_string(o.mapping.trials);
  progress.update("optimising: " + o.optimizer.method + ", trial 0/" + trials, true);
  const mapping::MappingResult mr = mapping::optimize_map(set, o.mapping, [&](std::size_t done) {
    progress.update(
        "optimising: " + o.optimizer.method + ", trial " + std::to_string(done) + "/" + trials,
        done == o.mapping.trials);
  });
  write_atomically(o.out / "trajectory.tum",
                   [&](std::ostream& out) { slam::write_tum(out, mr.corrected); });
  write_atomically(o.out / "trajectory-scan-matcher.tum",
                   [&](std::ostream& out) { slam::write_tum(out, fr.trajectory); });

  const auto maps_start = std::chrono::steady_clock::now();
  std::vector<std::filesystem::path> maps;
  if (!o.no_maps) maps = write_maps(o, log, fr, mr, progress);
  const double maps_s = seconds_since(maps_start);
  progress.update("evaluating", true);
  const std::optional<MapEvaluation> evaluation = evaluate(o, fr, mr);
  progress.clear();

  nlohmann::json report = frontend_input_json(o.log.string(), log, o.frontend);
  report["frontend"] = frontend_result_json(fr);
  report["optimization"] = optimization_json(set, o.mapping, mr);
  report["closures"] = closures_json(set, mr);
  if (evaluation) report["evaluation"] = evaluation_json(*evaluation);
  report["times"] = {{"read_s", read_s},
                     {"frontend_s", frontend_s},
                     {"scan_matching_s", fr.stats.matching_seconds},
                     {"loop_closure_s", fr.stats.closure_seconds},
                     {"optimization_s", mr.seconds},
                     {"maps_s", maps_s},
                     {"total_s", seconds_since(start)}};
  write_atomically(o.out / "report.json",
                   [&](std::ostream& out) { out << report.dump(2) << '\n'; });

  print_summary(o, fr, mr, evaluation);
  std::printf("wrote %s, %s, %s, %s\n", (o.out / "fragment-set.json").string().c_str(),
              (o.out / "trajectory.tum").string().c_str(),
              (o.out / "trajectory-scan-matcher.tum").string().c_str(),
              (o.out / "report.json").string().c_str());
  for (const std::filesystem::path& p : maps) std::printf("map: %s\n", p.string().c_str());
}

}  // namespace

void add_map_command(CLI::App& app) {
  auto options = std::make_shared<MapOptions>();
  MapOptions& o = *options;
  o.optimizer.method = std::string(slam::to_string(o.mapping.optimize.method));
  o.mapping.threads = 0;
  CLI::App* sub = app.add_subcommand(
      "map",
      "The whole AntSLAM pipeline on a CARMEN laser log: frontend, fragment set, optimisation, "
      "corrected trajectory, maps and a JSON report");
  sub->add_option("log", o.log, "CARMEN log (.clf/.log, may be gzipped)")->required();
  sub->add_option("--out", o.out, "output directory")->required();
  sub->add_option("--trials", o.mapping.trials,
                  "optimizer trials; the lowest weight is the map, all of them the average map")
      ->check(non_negative_integer())
      ->capture_default_str();
  sub->add_option("--threads", o.mapping.threads,
                  "threads the trials run on (0 = all cores); results do not depend on it")
      ->check(non_negative_integer())
      ->capture_default_str();
  sub->add_option("--reference", o.reference,
                  "reference trajectory (TUM) to evaluate both trajectories against");
  sub->add_flag("--no-maps", o.no_maps, "do not draw the maps");
  add_optimizer_options(*sub, o.optimizer);
  add_frontend_options(*sub, o.frontend);
  add_map_options(*sub, o.frontend);
  sub->callback([options] { run(*options); });
}

}  // namespace antslam::cli
