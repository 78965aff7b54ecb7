// The pipeline in one call (mapping::run_pipeline): on a simulated loop it returns the frontend's
// fragment set, the optimizer's corrected trajectory, the three maps and the evaluation against
// the simulator's ground truth, all consistent with the components run one by one; its report
// holds every part; bad settings and a missing reference fail before the log is read.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "antslam/frontend/frontend.hpp"
#include "antslam/frontend/simulator.hpp"
#include "antslam/mapping/pipeline.hpp"
#include "antslam/mapping/report.hpp"

namespace antslam::mapping {
namespace {

using namespace antslam::frontend;

const SimulatedRun& simulated_loop() {
  static const SimulatedRun run = [] {
    SimulationSettings sim;
    sim.beams = 181;
    sim.step = 0.35;
    std::vector<Eigen::Vector2d> path = loop_waypoints();
    path.push_back(Eigen::Vector2d(8, 0));
    SimulatedRun r = simulate_run(loop_world(), path, sim, 4);
    r.log.source = "some/folder/loop.clf";
    return r;
  }();
  return run;
}

PipelineSettings quick_settings() {
  PipelineSettings s;
  s.mapping.trials = 3;
  s.mapping.optimize.iterations = 30;
  s.map.resolution = 0.2;
  return s;
}

TEST(Pipeline, OneCallEqualsTheComponentsRunOneByOne) {
  const SimulatedRun& run = simulated_loop();
  const PipelineSettings s = quick_settings();
  std::vector<std::string> stages;
  const PipelineResult r = run_pipeline(run.log, s, Reference{"truth", run.truth},
                                        [&](std::string_view stage, bool final) {
                                          if (final) stages.emplace_back(stage);
                                        });

  const FrontendResult fr = run_frontend(run.log, s.frontend);
  EXPECT_EQ(r.frontend.fragment_set.name, "loop.clf");
  ASSERT_EQ(r.frontend.trajectory.size(), fr.trajectory.size());
  EXPECT_EQ(r.frontend.fragment_set.closures.size(), fr.fragment_set.closures.size());
  const MappingResult m = optimize_map(fr.fragment_set, s.mapping);
  EXPECT_EQ(r.mapping.best, m.best);
  EXPECT_EQ(r.mapping.trials[r.mapping.best].scores.weight, m.trials[m.best].scores.weight);
  ASSERT_EQ(r.mapping.corrected.size(), run.truth.size());
  for (std::size_t k = 0; k < m.corrected.size(); k += 13)
    EXPECT_EQ(r.mapping.corrected[k].pose.x, m.corrected[k].pose.x);

  ASSERT_TRUE(r.maps.has_value());
  EXPECT_EQ(r.maps->optimized.width(), r.maps->average.width());
  EXPECT_GT(r.maps->scan_matcher.width() * r.maps->scan_matcher.height(), 100U);
  ASSERT_TRUE(r.evaluation.has_value());
  EXPECT_EQ(r.evaluation->reference, "truth");
  EXPECT_EQ(r.evaluation->optimized.associated, run.truth.size());
  // The loop closes: the corrected trajectory is closer to the truth than the scan matcher's.
  EXPECT_LT(r.evaluation->optimized.ate.translation_m.rmse,
            r.evaluation->scan_matcher.ate.translation_m.rmse);
  EXPECT_LE(r.times.frontend_s + r.times.optimization_s + r.times.maps_s, r.times.total_s);

  ASSERT_FALSE(stages.empty());
  EXPECT_EQ(stages.front(), "optimising: hybrid+nlopt, trial 0/3");
  EXPECT_NE(std::find(stages.begin(), stages.end(), "optimising: hybrid+nlopt, trial 3/3"),
            stages.end());
  EXPECT_EQ(stages.back(), "evaluating");

  const nlohmann::json report = report_json("loop.clf", s, r);
  EXPECT_EQ(report["scans"], run.truth.size());
  EXPECT_EQ(report["closures"].size(), r.frontend.fragment_set.closures.size());
  EXPECT_EQ(report["optimization"]["trials"], 3);
  EXPECT_EQ(report["optimization"]["method"], "hybrid+nlopt");
  EXPECT_EQ(report["settings"]["map_resolution_m"], 0.2);
  EXPECT_TRUE(report.contains("evaluation"));
  EXPECT_TRUE(report["times"].contains("total_s"));
}

TEST(Pipeline, WithoutMapsOrReferenceItDrawsAndEvaluatesNothing) {
  PipelineSettings s = quick_settings();
  s.draw_maps = false;
  s.mapping.trials = 1;
  const PipelineResult r = run_pipeline(simulated_loop().log, s);
  EXPECT_FALSE(r.maps.has_value());
  EXPECT_FALSE(r.evaluation.has_value());
  EXPECT_FALSE(report_json("loop.clf", s, r).contains("evaluation"));
}

TEST(Pipeline, MapsTooLargeForThePixelCapAreDrawnCoarserAndTheVerdictCounts) {
  PipelineSettings s = quick_settings();
  s.mapping.trials = 1;
  s.map.resolution = 0.01;
  s.map.max_pixels = 200000;  // the ring (about 30 m x 24 m) would need 7 million at 1 cm
  const PipelineResult r = run_pipeline(simulated_loop().log, s);
  ASSERT_TRUE(r.maps.has_value());
  EXPECT_GT(r.maps->resolution, 0.05);
  EXPECT_LE(r.maps->scan_matcher.width() * r.maps->scan_matcher.height(), s.map.max_pixels);
  EXPECT_LE(r.maps->average.width() * r.maps->average.height(), s.map.max_pixels);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.back().find("maps drawn at"), std::string::npos) << r.warnings.back();
  const nlohmann::json report = report_json("loop.clf", s, r);
  EXPECT_EQ(report["maps"]["resolution_m"], r.maps->resolution);
  EXPECT_EQ(report["warnings"].back(), r.warnings.back());

  // The simulated loop closes: every closure within 2 sigma, no fallback, a consistent map.
  const Verdict& v = r.verdict;
  EXPECT_EQ(v.closures, r.frontend.fragment_set.closures.size());
  EXPECT_EQ(v.scans, simulated_loop().log.scans.size());
  EXPECT_TRUE(v.outside.empty());
  EXPECT_EQ(v.fallbacks, 0U);
  EXPECT_FALSE(v.doubtful);
  EXPECT_EQ(v.line.rfind("verdict: consistent map: ", 0), 0U) << v.line;
  EXPECT_EQ(report["verdict"]["line"], v.line);
  // The same map judged with a closure ellipse of nought: every closure is outside.
  VerdictSettings strict;
  strict.closure_sigmas = 0.0;
  const Verdict w = judge(r.frontend, r.mapping, strict);
  EXPECT_EQ(w.outside.size(), w.closures);
  EXPECT_TRUE(w.doubtful);
  EXPECT_EQ(w.line.rfind("verdict: DOUBTFUL map: 0 of ", 0), 0U) << w.line;
  double largest = 0.0;
  for (const ClosureResidual& c : r.mapping.after) largest = std::max(largest, c.mahalanobis);
  EXPECT_DOUBLE_EQ(w.largest_closure, largest);
}

TEST(Pipeline, NoClosureMeansNothingToOptimise) {
  PipelineSettings s = quick_settings();
  s.frontend.closure.enabled = false;
  try {
    run_pipeline(simulated_loop().log, s);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("found no loop closure"), std::string::npos) << e.what();
  }
}

TEST(Pipeline, SettingsAndReferenceAreCheckedBeforeTheLogIsRead) {
  const std::filesystem::path missing = "no/such/log.clf";
  PipelineSettings s = quick_settings();
  s.mapping.trials = 0;
  EXPECT_THROW(run_pipeline(missing, s), std::invalid_argument);
  try {
    run_pipeline(missing, quick_settings(), "no/such/reference.tum");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "no/such/reference.tum: cannot open the reference trajectory");
  }
}

}  // namespace
}  // namespace antslam::mapping
