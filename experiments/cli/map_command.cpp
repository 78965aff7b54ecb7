// antslam map LOG --out DIR: the whole AntSLAM pipeline on a CARMEN laser log.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/atomic_file.hpp"
#include "cli/progress.hpp"
#include "commands.hpp"
#include "eval/evaluation.hpp"
#include "frontend/mapping.hpp"
#include "frontend/map_render.hpp"
#include "slamgraph/fragment_set_io.hpp"
#include "slamgraph/trials.hpp"

namespace antslam::cli {

namespace {

namespace fe = antslam::frontend;

struct MapOptions {
  std::filesystem::path log, out, reference;
  std::string method = "hybrid+nlopt";
  fe::MappingSettings settings;
  fe::SensorOverrides sensor;
  fe::MapRenderSettings map;
  bool no_maps = false;
};

void run(MapOptions o) {
  o.settings.optimize.method = slam::parse_method(o.method);
  const fe::LaserLog log = fe::read_carmen_file(o.log, o.sensor);
  Progress progress;
  fe::Frontend frontend(o.settings.frontend, o.log.filename().string());
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    frontend.add_scan(log.scans[i]);
    progress.update("frontend: scan " + std::to_string(i + 1) + "/" + std::to_string(log.scans.size()));
  }
  const fe::FrontendResult fr = frontend.finish();
  write_atomically(o.out / "fragment-set.json",
                   [&](std::ostream& out) { slam::write_fragment_set(out, fr.fragment_set); });
  progress.update("optimising", true);
  const fe::MappingResult mr = fe::optimize_map(fr, o.settings);
  progress.clear();
  write_atomically(o.out / "trajectory.tum",
                   [&](std::ostream& out) { slam::write_tum(out, mr.corrected); });
  write_atomically(o.out / "trajectory-scan-matcher.tum",
                   [&](std::ostream& out) { slam::write_tum(out, fr.trajectory); });
  const slam::OptimizeResult& best = mr.trials[mr.best];
  std::printf("%zu fragments, %zu closures; scan matcher weight %.4f chi2 %.4g; best weight %.4f chi2 %.4g (%.2f s)\n",
              fr.fragment_set.fragments.size(), fr.fragment_set.closures.size(),
              mr.scan_matcher.weight, mr.scan_matcher.chi2, best.scores.weight, best.scores.chi2,
              mr.seconds);
  for (std::size_t c = 0; c < mr.after.size(); ++c)
    std::printf("  closure %zu-%zu: mahalanobis %.2f -> %.2f\n", mr.after[c].from, mr.after[c].to,
                mr.before[c].mahalanobis, mr.after[c].mahalanobis);
  if (!o.reference.empty()) {
    const slam::Trajectory ref = slam::read_tum_file(o.reference);
    const eval::Evaluation a = eval::evaluate(fr.trajectory, ref, {});
    const eval::Evaluation b = eval::evaluate(mr.corrected, ref, {});
    std::printf("ATE rmse: scan matcher %.4f m, optimised %.4f m\n", a.ate.translation_m.rmse,
                b.ate.translation_m.rmse);
  }
  if (!o.no_maps) {
    const fe::MapLayout layout = fe::map_layout(fr);
    write_atomically(o.out / "map-scan-matcher.png",
                     fe::encode_png(fe::render_map(log, layout, fe::scan_matcher_frames(fr), o.map)));
    write_atomically(o.out / "map-optimized.png",
                     fe::encode_png(fe::render_map(log, layout, best.frames, o.map)));
  }
}

}  // namespace

void add_map_command(CLI::App& app) {
  auto options = std::make_shared<MapOptions>();
  MapOptions& o = *options;
  CLI::App* sub = app.add_subcommand("map", "The whole AntSLAM pipeline on a CARMEN laser log");
  sub->add_option("log", o.log)->required();
  sub->add_option("--out", o.out)->required();
  sub->add_option("--method", o.method);
  sub->add_option("--trials", o.settings.trials);
  sub->add_option("--threads", o.settings.threads);
  sub->add_option("--seed", o.settings.optimize.seed);
  sub->add_option("--laser-offset", o.sensor.laser_offset);
  sub->add_option("--reference", o.reference);
  sub->add_option("--covariance-scale", o.settings.frontend.fragmentation.covariance_scale);
  sub->add_option("--closure-temperature", o.settings.frontend.closure.temperature);
  sub->add_option("--fragment-length", o.settings.frontend.fragmentation.length);
  sub->add_flag("--no-maps", o.no_maps);
  sub->callback([options] { run(*options); });
}

}  // namespace antslam::cli
