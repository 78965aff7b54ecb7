// antslam map LOG --out-dir DIR: the whole AntSLAM pipeline on a CARMEN laser log (paper Secs.
// III-IV, mapping::run_pipeline). Writes the fragment set, the corrected and the scan-matcher
// trajectories (TUM, every scan), the scan-matcher map (Fig. 5a), the optimized map, the average
// map of the trials (Fig. 5b) and a JSON report; prints every closure's Mahalanobis distance
// before and after.

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "antslam/frontend/image.hpp"
#include "antslam/io/errors.hpp"
#include "antslam/io/json_output.hpp"
#include "antslam/io/output_files.hpp"
#include "antslam/io/progress.hpp"
#include "antslam/mapping/pipeline.hpp"
#include "antslam/mapping/report.hpp"
#include "antslam/slamgraph/fragment_set_io.hpp"
#include "commands.hpp"
#include "frontend_options.hpp"
#include "optimizer_options.hpp"
#include "output_options.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

struct MapOptions {
  std::filesystem::path log, out, reference;
  FrontendOptions frontend;
  OptimizerOptions optimizer;  ///< --method defaults to hybrid+nlopt (add_map_command)
  mapping::MappingSettings mapping;
  bool no_maps = false;
};

/// Closures are listed one a line up to this many; beyond, only those outside 2 sigma.
constexpr std::size_t kListedClosures = 20;

void print_summary(const MapOptions& o, const mapping::PipelineResult& r) {
  const slam::FragmentSet& set = r.frontend.fragment_set;
  const mapping::MappingResult& mr = r.mapping;
  const slam::OptimizeResult& best = mr.trials[mr.best];
  std::printf("%s: %zu scans, %zu fragments, %zu loop closures (frontend %.2f s)\n",
              o.log.string().c_str(), r.frontend.trajectory.size(), set.fragments.size(),
              set.closures.size(),
              r.frontend.stats.matching_seconds + r.frontend.stats.closure_seconds);
  std::printf("%s, %zu trials (%.2f s): weight (eq. 10) %.4f -> %.4f, chi2 %.6g -> %.6g\n",
              o.optimizer.method.c_str(), mr.trials.size(), mr.seconds, mr.scan_matcher.weight,
              best.scores.weight, mr.scan_matcher.chi2, best.scores.chi2);
  if (mr.closing) {
    std::string distrusted;
    for (std::size_t c = 0; c < set.closures.size(); ++c)
      if (!mr.closing->trusted[c])
        distrusted +=
            " " + std::to_string(set.closures[c].from) + "-" + std::to_string(set.closures[c].to);
    const auto trusted = static_cast<std::size_t>(
        std::count(mr.closing->trusted.begin(), mr.closing->trusted.end(), true));
    std::printf(
        "loops closed by least squares with %zu of %zu closures (%s; %s%s): weight %.4f, "
        "chi2 %.6g\n",
        trusted, set.closures.size(),
        std::string(mapping::to_string(o.mapping.closing.selection)).c_str(),
        distrusted.empty() ? "all consistent" : "distrusted:", distrusted.c_str(), mr.scores.weight,
        mr.scores.chi2);
  }
  std::printf(
      "loop closures (Mahalanobis distance of the residual, scan matcher -> optimized)%s:\n",
      mr.after.size() > kListedClosures ? ", those outside 2 sigma" : "");
  for (std::size_t c = 0; c < mr.after.size(); ++c) {
    const bool ok = mr.after[c].mahalanobis <= mapping::kClosureSigmas;
    if (ok && mr.after.size() > kListedClosures) continue;
    std::printf("  %3zu-%-3zu %9.2f -> %6.2f  %s\n", mr.after[c].from, mr.after[c].to,
                mr.before[c].mahalanobis, mr.after[c].mahalanobis,
                ok ? "within 2 sigma" : "OUTSIDE 2 sigma");
  }
  std::printf("  %zu of %zu closures within their 2-sigma ellipse\n",
              mr.after.size() - r.verdict.outside.size(), mr.after.size());
  if (r.evaluation)
    std::printf("ATE RMSE vs %s: scan matcher %.4f m, optimized %.4f m (%zu poses)\n",
                r.evaluation->reference.c_str(), r.evaluation->scan_matcher.ate.translation_m.rmse,
                r.evaluation->optimized.ate.translation_m.rmse, r.evaluation->optimized.associated);
  for (const std::size_t c : r.verdict.outside)
    std::printf("warning: loop closure %zu-%zu is %.2f sigma from its hypothesis in the map\n",
                mr.after[c].from, mr.after[c].to, mr.after[c].mahalanobis);
  for (const std::string& w : r.warnings) std::printf("warning: %s\n", w.c_str());
}

void run(MapOptions o) {
  resolve(o.frontend);
  mapping::PipelineSettings s;
  s.sensor = o.frontend.sensor.overrides();
  s.frontend = o.frontend.settings;
  s.mapping = o.mapping;
  s.mapping.optimize = optimize_settings(o.optimizer);
  s.mapping.backend = s.mapping.optimize.backend;
  s.frontend.fragmentation.seed = s.mapping.optimize.seed;
  s.map = o.frontend.map;
  s.draw_maps = !o.no_maps;
  mapping::validate(s);

  // Every output is declared (and checked) now; maps this run does not draw are removed from
  // --out when the outputs are moved into place, so that the directory holds one run.
  io::OutputFiles outputs;
  const std::filesystem::path set_path = outputs.add(o.out / "fragment-set.json");
  const std::filesystem::path trajectory = outputs.add(o.out / "trajectory.tum");
  const std::filesystem::path scan_matcher = outputs.add(o.out / "trajectory-scan-matcher.tum");
  const std::vector<std::filesystem::path> maps = {outputs.add(o.out / "map-scan-matcher.png"),
                                                   outputs.add(o.out / "map-optimized.png"),
                                                   outputs.add(o.out / "map-average.png")};
  const std::filesystem::path report = outputs.add(o.out / "report.json");

  io::Progress progress;
  const mapping::PipelineResult r = io::in_context_of({o.log, o.reference}, [&] {
    return mapping::run_pipeline(o.log, s, o.reference, [&](std::string_view stage, bool final) {
      progress.update(std::string(stage), final);
    });
  });
  progress.clear();

  // The maps last: the trajectory, fragment set and report are there whatever happens to them.
  outputs.write(set_path,
                [&](std::ostream& out) { slam::write_fragment_set(out, r.frontend.fragment_set); });
  outputs.write(trajectory, [&](std::ostream& out) { slam::write_tum(out, r.mapping.corrected); });
  outputs.write(scan_matcher,
                [&](std::ostream& out) { slam::write_tum(out, r.frontend.trajectory); });
  outputs.write(report, io::json_text(mapping::report_json(o.log.string(), s, r)));
  if (r.maps) {
    outputs.write(maps[0], frontend::encode_png(r.maps->scan_matcher));
    outputs.write(maps[1], frontend::encode_png(r.maps->optimized));
    outputs.write(maps[2], frontend::encode_png(r.maps->average));
  }
  outputs.commit();

  print_summary(o, r);
  std::printf("wrote %s, %s, %s, %s\n", set_path.string().c_str(), trajectory.string().c_str(),
              scan_matcher.string().c_str(), report.string().c_str());
  if (r.maps)
    for (const std::filesystem::path& p : maps)
      std::printf("map: %s (%.3f m per pixel)\n", p.string().c_str(), r.maps->resolution);
  std::printf("%s\n", r.verdict.line.c_str());
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
  add_out_dir_option(*sub, o.out, "output directory (required)");
  sub->add_option("--trials", o.mapping.trials,
                  "optimizer trials; the lowest weight is the map, all of them the average map")
      ->check(count_in(1, kMaxTrials))
      ->capture_default_str();
  sub->add_option("--threads", o.mapping.threads,
                  "threads the trials run on (0 = all cores); results do not depend on it")
      ->check(count_in(0, kMaxThreads))
      ->capture_default_str();
  sub->add_option("--reference", o.reference,
                  "reference trajectory (TUM) to evaluate both trajectories against");
  sub->add_flag("--no-maps", o.no_maps, "do not draw the maps");
  std::vector<std::string> selections;
  std::string help = "which closures the loops are closed with:";
  for (const mapping::ClosureSelectionInfo& info : mapping::kClosureSelections) {
    selections.emplace_back(info.name);
    help += " " + std::string(info.name) + " (" + std::string(info.summary) + ")";
  }
  sub->add_option_function<std::string>(
         "--closures",
         [&o](const std::string& name) {
           o.mapping.closing.selection = *mapping::parse_closure_selection(name);
         },
         help)
      ->check(CLI::IsMember(selections))
      ->default_str(std::string(mapping::to_string(o.mapping.closing.selection)));
  sub->add_flag(
      "--no-closing", [&o](std::int64_t) { o.mapping.closing.enabled = false; },
      "keep the best trial's map: do not close the loops with the trusted closures by least "
      "squares afterwards");
  add_optimizer_options(*sub, o.optimizer);
  add_frontend_options(*sub, o.frontend);
  add_map_options(*sub, o.frontend);
  sub->callback([options] {
    require_output(!options->out.empty(), "--out-dir");
    run(*options);
  });
}

}  // namespace antslam::cli
