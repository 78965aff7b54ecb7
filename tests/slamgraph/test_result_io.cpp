// The result file and the CSV outputs.

#include <gtest/gtest.h>

#include <sstream>

#include "slamgraph/result_io.hpp"
#include "slamgraph/synth.hpp"
#include "support.hpp"

namespace antslam::slam {
namespace {

TEST(ResultIo, RoundTrip) {
  const FragmentSet set = synthesize(synth_preset("paper9"));
  OptimizeSettings s;
  s.iterations = 30;
  s.seed = 4;
  const auto trials = run_trials(set, s, 3, 1);
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
  std::ostringstream trials, convergence;
  write_trials_csv(trials, std::vector<OptimizeResult>{a}, 9);
  write_convergence_csv(convergence, std::vector<OptimizeResult>{a});
  EXPECT_EQ(trials.str(),
            "trial,seed,weight,chi2,iterations,evaluations,elapsed_s,time_to_best_s\n0," +
                std::to_string(trial_seed(9, 0)) + ",1.5,10,3,60,0,0\n");
  EXPECT_EQ(
      convergence.str(),
      "trial,iteration,evaluations,elapsed_s,best_weight\n0,1,20,0.001,2\n0,3,60,0.002,1.5\n");
}

}  // namespace
}  // namespace antslam::slam
