// The result file and the CSV outputs.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "antslam/aco/parameter_fields.hpp"
#include "antslam/slamgraph/result_io.hpp"
#include "antslam/slamgraph/synth.hpp"
#include "antslam/version.hpp"
#include "support.hpp"

namespace antslam::slam {
namespace {

TEST(ResultIo, RoundTrip) {
  const FragmentSet set = synthesize(synth_preset("paper9"));
  OptimizeSettings s;
  s.iterations = 30;
  s.seed = 4;
  const auto trials = run_trials(set, s, {.trials = 3, .threads = 1});
  StudyResult r = summarize("paper9.json", s, trials);
  r.error = TrajectoryError{0.25, 0.5, 1.5, 9};
  std::ostringstream out;
  write_result(out, r);
  std::istringstream in(out.str());
  const StudyResult back = read_result(in, "result.json");
  EXPECT_EQ(back.fragment_set, "paper9.json");
  EXPECT_EQ(back.method, Method::hybrid);
  EXPECT_EQ(back.trials, 3U);
  EXPECT_EQ(back.seed, 4U);
  EXPECT_EQ(back.best_trial, r.best_trial);
  EXPECT_EQ(back.weight.std, r.weight.std);
  EXPECT_EQ(back.best.choice, r.best.choice);
  EXPECT_EQ(back.best.scores.weight, r.best.scores.weight);
  EXPECT_EQ(back.best.frames.back().theta, r.best.frames.back().theta);
  EXPECT_EQ(back.error->rmse_m, 0.25);
  EXPECT_EQ(back.error->rmse_deg, 1.5);
  EXPECT_EQ(back.error->poses, 9U);
  for (const OptimizeResult& t : trials) EXPECT_GE(t.scores.weight, r.best.scores.weight);
  EXPECT_EQ(r.weight.min, r.best.scores.weight);
}

TEST(ResultIo, TheSettingsThatDecideTheResultReadBack) {
  const FragmentSet set = synthesize(synth_preset("paper9"));
  OptimizeSettings s;
  s.method = Method::hybrid_nlopt;
  s.iterations = 20;
  s.seed = 9;
  s.aco.rho = 0.25;
  s.aco.ants = 7;
  s.aco.restarts = false;
  s.aco.alpha = 1.25;
  s.aco.beta = 3.0;
  s.aco.q0 = 0.7;
  s.aco.xi = 0.2;
  s.aco.elite_weight = 3.0;
  s.aco.rank_width = 4;
  s.aco.p_best = 0.1;
  s.aco.restart_stagnant = 11;
  s.aco.glob_best_freq = 7;
  s.aco.tau_max = 123.5;
  s.aco.tau_init = 50.0;
  s.aco.hybrid_deposit = 2.5;
  s.refine.algorithm = RefineAlgorithm::slsqp;
  s.refine.max_evaluations = 123;
  s.refine.graduated = false;
  s.ceres.max_iterations = 17;
  s.threads = 2;
  const auto trials = run_trials(set, s, {.trials = 1, .threads = 2});
  StudyResult r = summarize("paper9.json", s, trials);
  r.settings->islands = aco::IslandSettings{
      .colonies = 4, .exchange_every = 9, .topology = aco::Topology::full, .first = 2};
  std::ostringstream out;
  write_result(out, r);
  std::istringstream in(out.str());
  const StudyResult back = read_result(in, "result.json");
  ASSERT_TRUE(back.settings.has_value());
  const OptimizeSettings& b = *back.settings;
  EXPECT_EQ(b.method, Method::hybrid_nlopt);
  EXPECT_EQ(b.seed, 9U);
  EXPECT_EQ(b.iterations, 20U);
  EXPECT_EQ(b.aco.rho, 0.25);
  EXPECT_EQ(b.aco.ants, 7U);
  EXPECT_FALSE(b.aco.restarts);
  EXPECT_EQ(b.aco.p0, s.aco.p0);
  const auto numbers = [](const aco::Parameters& p) {
    std::vector<double> v;
    aco::for_each_parameter(p, [&](const char*, const auto& x) { v.push_back(double(x)); });
    return v;
  };
  EXPECT_EQ(numbers(b.aco), numbers(s.aco));  // every engine parameter, as written
  EXPECT_NE(out.str().find(std::string("\"antslam_version\": \"") + kVersion + "\""),
            std::string::npos);
  EXPECT_EQ(b.refine.algorithm, RefineAlgorithm::slsqp);
  EXPECT_EQ(b.refine.max_evaluations, 123);
  EXPECT_FALSE(b.refine.graduated);
  EXPECT_EQ(b.ceres.max_iterations, 17);
  ASSERT_TRUE(b.islands.has_value());
  EXPECT_EQ(b.islands->colonies, 4U);
  EXPECT_EQ(b.islands->exchange_every, 9U);
  EXPECT_EQ(b.islands->topology, aco::Topology::full);
  EXPECT_EQ(out.str().find("\"threads\""), std::string::npos);  // not part of the result
  std::string bad = out.str();
  const std::string rho = "\"rho\":0.25";
  bad.replace(bad.find(rho), rho.size(), "\"rho\":1.5");
  std::istringstream bad_in(bad);
  EXPECT_EQ(testing::error_of([&] { read_result(bad_in, "r.json"); }),
            "r.json: settings: optimize: aco: rho must be in [0, 1] (0: the variant's default)");
}

TEST(ResultIo, AnInterruptedStudySaysSoAndReadsBack) {
  const FragmentSet set = synthesize(synth_preset("paper9"));
  OptimizeSettings s;
  s.iterations = 30;
  const auto trials = run_trials(set, s, {.trials = 2, .threads = 1});
  StudyResult r = summarize("paper9.json", s, trials);
  std::ostringstream complete;
  write_result(complete, r);
  EXPECT_EQ(complete.str().find("interrupted"), std::string::npos);
  r.interrupted = StudyInterruption{"SIGTERM", 10};
  std::ostringstream out;
  write_result(out, r);
  EXPECT_NE(out.str().find("\"interrupted\": true"), std::string::npos);
  std::istringstream in(out.str());
  const StudyResult back = read_result(in, "result.json");
  ASSERT_TRUE(back.interrupted.has_value());
  EXPECT_EQ(back.interrupted->signal, "SIGTERM");
  EXPECT_EQ(back.interrupted->trials_requested, 10U);
  EXPECT_EQ(back.trials, 2U);
  std::string fewer = out.str();
  const std::string ten = "\"trials_requested\": 10";
  fewer.replace(fewer.find(ten), ten.size(), "\"trials_requested\": 1");
  std::istringstream bad(fewer);
  EXPECT_EQ(testing::error_of([&] { read_result(bad, "r.json"); }),
            "r.json: trials_requested: must be >= trials");
}

TEST(ResultIo, RejectsBadFiles) {
  const auto error_of = [](const std::string& text) {
    return testing::error_of([&] {
      std::istringstream in(text);
      read_result(in, "r.json");
    });
  };
  EXPECT_EQ(error_of(R"({"format": "antslam-fragment-set", "version": 1})"),
            "r.json: format: expected \"antslam-optimize-result\"");
  EXPECT_EQ(error_of(R"({"format": "antslam-optimize-result", "version": 1, "fragment_set": "x",
                      "method": "ants"})"),
            "r.json: method: unknown method 'ants' (expected one of as, eas, ras, acs, mmas, "
            "hybrid, hybrid+nlopt, nlopt, ceres, ceres-robust, random, exhaustive)");
}

TEST(ResultIo, CsvFiles) {
  OptimizeResult a;
  a.scores = {1.5, 10.0};
  a.iterations = 3;
  a.evaluations = 60;
  a.convergence = {{1, 20, 0.001, 2.0}, {3, 60, 0.002, 1.5}};
  a.elapsed_s = 0.004;
  a.time_to_best_s = 0.002;
  std::ostringstream trials, convergence, times;
  write_trials_csv(trials, std::vector<OptimizeResult>{a}, 9);
  write_convergence_csv(convergence, std::vector<OptimizeResult>{a});
  write_times_json(times, std::vector<OptimizeResult>{a});
  EXPECT_EQ(trials.str(), "trial,seed,weight,chi2,iterations,evaluations\n0," +
                              std::to_string(trial_seed(9, 0)) + ",1.5,10,3,60\n");
  EXPECT_EQ(convergence.str(), "trial,iteration,evaluations,best_weight\n0,1,20,2\n0,3,60,1.5\n");
  const auto doc = nlohmann::json::parse(times.str());
  EXPECT_EQ(doc["format"], "antslam-optimize-times");
  EXPECT_EQ(doc["elapsed_s"]["mean"], 0.004);
  EXPECT_EQ(doc["trials"][0]["time_to_best_s"], 0.002);
  EXPECT_EQ(doc["trials"][0]["convergence"], nlohmann::json::parse("[[1, 0.001], [3, 0.002]]"));
}

TEST(ResultIo, ResultFileHasNoTimesAndIsTheSameOnEveryThreadCount) {
  const FragmentSet set = synthesize(synth_preset("paper9"));
  OptimizeSettings s;
  s.iterations = 40;
  const auto text = [&](std::size_t threads, aco::BackendKind backend) {
    const auto trials = run_trials(set, s, {.trials = 4, .threads = threads, .backend = backend});
    std::ostringstream out;
    write_result(out, summarize("paper9", s, trials));
    write_trials_csv(out, trials, s.seed);
    write_convergence_csv(out, trials);
    return out.str();
  };
  const std::string serial = text(1, aco::BackendKind::serial);
  EXPECT_EQ(serial.find("elapsed"), std::string::npos);
  EXPECT_EQ(text(2, aco::BackendKind::omp), serial);
  EXPECT_EQ(text(2, aco::BackendKind::tbb), serial);
}

TEST(ResultIo, ReadsVersionOneFilesWithTimes) {
  const FragmentSet set = synthesize(synth_preset("paper9"));
  OptimizeSettings s;
  s.iterations = 10;
  const auto trials = run_trials(set, s, {.trials = 1, .threads = 1});
  std::ostringstream out;
  write_result(out, summarize("paper9", s, trials));
  auto doc = nlohmann::json::parse(out.str());
  doc["version"] = 1;
  doc["elapsed_s"] = {{"mean", 0.5}, {"std", 0.0}, {"min", 0.5}, {"max", 0.5}};
  doc["best"]["elapsed_s"] = 0.5;
  doc["best"]["time_to_best_s"] = 0.25;
  std::istringstream in(doc.dump());
  const StudyResult back = read_result(in, "v1.json");
  EXPECT_EQ(back.elapsed_s.mean, 0.5);
  EXPECT_EQ(back.best.time_to_best_s, 0.25);
}

}  // namespace
}  // namespace antslam::slam
