#include "antslam/mapping/pipeline.hpp"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <vector>

namespace antslam::mapping {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void report(const StageObserver& observer, std::string_view stage, bool final) {
  if (observer) observer(stage, final);
}

/// The three maps at the finest resolution that fits the pixel cap (the same for all three).
PipelineMaps draw_maps(PipelineResult& r, frontend::MapRenderSettings settings,
                       const StageObserver& observer) {
  const frontend::MapLayout layout = frontend::map_layout(r.frontend);
  const MappingResult& m = r.mapping;
  std::vector<std::vector<slam::Pose2>> placements{m.scan_matcher_frames};
  for (const slam::OptimizeResult& t : m.trials) placements.push_back(t.frames);
  const double wanted = settings.resolution;
  settings.resolution = frontend::fitting_resolution(r.log, layout, placements, settings);
  if (settings.resolution > wanted) {
    char line[200];
    std::snprintf(line, sizeof line,
                  "maps drawn at %.3f m per pixel: at %.3f m they would exceed %zu pixels",
                  settings.resolution, wanted, settings.max_pixels);
    r.warnings.emplace_back(line);
  }
  report(observer, "maps: scan matcher", true);
  frontend::Image scan_matcher =
      frontend::render_map(r.log, layout, m.scan_matcher_frames, settings);
  report(observer, "maps: optimized", true);
  frontend::Image optimized = frontend::render_map(r.log, layout, m.frames, settings);
  report(observer, "maps: average of " + std::to_string(m.trials.size()) + " trials", true);
  placements.erase(placements.begin());
  return {std::move(scan_matcher), std::move(optimized),
          frontend::render_average_map(r.log, layout, placements, settings), settings.resolution};
}

}  // namespace

void validate(const PipelineSettings& settings) {
  frontend::validate(settings.frontend);
  frontend::validate(settings.map);
  validate(settings.mapping);
}

PipelineResult run_pipeline(frontend::LaserLog log, const PipelineSettings& settings,
                            const std::optional<Reference>& reference,
                            const StageObserver& observer) {
  const auto start = Clock::now();
  validate(settings);
  PipelineResult r;
  r.log = std::move(log);
  r.warnings = r.log.warnings;

  const auto frontend_start = Clock::now();
  r.frontend =
      frontend::run_frontend(r.log, settings.frontend, [&](const frontend::FrontendProgress& p) {
        if (observer) observer(frontend::to_string(p), false);
      });
  r.times.frontend_s = seconds_since(frontend_start);
  const slam::FragmentSet& set = r.frontend.fragment_set;
  if (set.closures.empty())
    throw std::invalid_argument(r.log.source + ": the frontend found no loop closure in " +
                                std::to_string(set.fragments.size()) +
                                " fragments, so there is nothing to optimise (antslam frontend "
                                "draws the scan-matcher map)");

  const std::string method(slam::to_string(settings.mapping.optimize.method));
  const std::string trials = std::to_string(settings.mapping.trials);
  report(observer, "optimising: " + method + ", trial 0/" + trials, true);
  r.mapping = optimize_map(set, settings.mapping, [&](std::size_t done) {
    report(observer, "optimising: " + method + ", trial " + std::to_string(done) + "/" + trials,
           done == settings.mapping.trials);
  });
  r.times.optimization_s = r.mapping.seconds;
  r.verdict = judge(r.frontend, r.mapping);

  // A run never dies for a picture: whatever goes wrong with the maps is a warning.
  const auto maps_start = Clock::now();
  if (settings.draw_maps) {
    try {
      r.maps = draw_maps(r, settings.map, observer);
    } catch (const std::exception& e) {
      r.warnings.push_back(std::string("maps not drawn: ") + e.what());
    }
  }
  r.times.maps_s = seconds_since(maps_start);

  if (reference) {
    report(observer, "evaluating", true);
    r.evaluation = MapEvaluation{reference->name,
                                 eval::evaluate(r.frontend.trajectory, reference->trajectory, {}),
                                 eval::evaluate(r.mapping.corrected, reference->trajectory, {})};
  }
  r.times.total_s = seconds_since(start);
  return r;
}

PipelineResult run_pipeline(const std::filesystem::path& log, const PipelineSettings& settings,
                            const std::filesystem::path& reference, const StageObserver& observer) {
  const auto start = Clock::now();
  validate(settings);
  std::optional<Reference> ref;
  if (!reference.empty()) {
    if (!std::filesystem::is_regular_file(reference))
      throw std::runtime_error(reference.string() + ": cannot open the reference trajectory");
    ref = Reference{reference.string(), slam::read_tum_file(reference)};
  }
  report(observer, "reading " + log.string(), true);
  frontend::LaserLog laser = frontend::read_carmen_file(log, settings.sensor);
  const double read_s = seconds_since(start);
  PipelineResult r = run_pipeline(std::move(laser), settings, ref, observer);
  r.times.read_s = read_s;
  r.times.total_s = seconds_since(start);
  return r;
}

}  // namespace antslam::mapping
