// Results sent between ranks (result_bytes.hpp): what the root writes from received results is
// byte for byte what it writes from the results it computed, and nothing is left over.

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "antslam/dist/result_bytes.hpp"
#include "antslam/slamgraph/result_io.hpp"
#include "antslam/slamgraph/synth.hpp"
#include "antslam/slamgraph/trials.hpp"

namespace antslam::cli {
namespace {

template <class T, class Read>
std::vector<T> round_trip(const std::vector<T>& values, Read read) {
  dist::ByteWriter out;
  for (const T& v : values) write(out, v);
  dist::ByteReader in(out.bytes());
  std::vector<T> back;
  for (std::size_t i = 0; i < values.size(); ++i) back.push_back(read(in));
  EXPECT_EQ(in.remaining(), 0U);
  dist::ByteWriter again;
  for (const T& v : back) write(again, v);
  EXPECT_EQ(again.bytes(), out.bytes());
  return back;
}

std::string optimize_outputs(const std::vector<slam::OptimizeResult>& trials,
                             const slam::OptimizeSettings& s) {
  std::ostringstream out;
  slam::write_result(out, slam::summarize("set.json", s, trials));
  slam::write_trials_csv(out, trials, s.seed);
  slam::write_convergence_csv(out, trials);
  slam::write_times_json(out, trials);
  return out.str();
}

TEST(ResultBytes, OptimizeResultsWriteTheSameFilesAfterTheTrip) {
  const slam::FragmentSet set = slam::synthesize(slam::synth_preset("paper9"));
  for (const slam::Method m : {slam::Method::hybrid, slam::Method::hybrid_nlopt}) {
    slam::OptimizeSettings s;
    s.method = m;
    s.seed = 3;
    s.iterations = 40;
    const auto trials = slam::run_trials(set, s, {.trials = 3, .threads = 1});
    const auto back = round_trip(trials, dist::read_optimize_result);
    EXPECT_EQ(optimize_outputs(back, s), optimize_outputs(trials, s));
    EXPECT_EQ(back[2].frames.size(), 9U);
    EXPECT_EQ(back[2].colony.has_value(), trials[2].colony.has_value());
  }
}

TEST(ResultBytes, TspRunsWriteTheSameFilesAfterTheTrip) {
  tsp::ExperimentSettings e;
  e.instances = {std::filesystem::path(ANTSLAM_DATA_DIR) / "tsplib" / "eil51.tsp"};
  e.seeds = 2;
  e.termination.max_iterations = 5;
  const auto runs = tsp::run_experiment(e);
  const auto back = round_trip(runs, dist::read_experiment_run);
  std::ostringstream a, b;
  tsp::write_runs_csv(a, runs, "2-opt");
  tsp::write_summary_markdown(a, runs, "2-opt");
  tsp::write_runs_csv(b, back, "2-opt");
  tsp::write_summary_markdown(b, back, "2-opt");
  EXPECT_EQ(b.str(), a.str());
  EXPECT_EQ(back[1].result.best.path, runs[1].result.best.path);
  EXPECT_EQ(back[1].optimum, runs[1].optimum);
  EXPECT_TRUE(back[1].optimum.has_value());  // eil51: 426 in optima.csv
}

TEST(ResultBytes, AnOptionalIsAPresenceByteAndThenItsValue) {
  dist::ByteWriter out;
  out.optional(std::optional<double>());
  out.optional(std::optional<double>(2.5));
  ASSERT_EQ(out.bytes().size(), 1U + 1U + sizeof(double));
  EXPECT_EQ(out.bytes()[0], std::byte{0});
  EXPECT_EQ(out.bytes()[1], std::byte{1});
  dist::ByteReader in(out.bytes());
  EXPECT_FALSE(in.optional<double>().has_value());
  EXPECT_EQ(in.optional<double>(), 2.5);
  EXPECT_EQ(in.remaining(), 0U);
}

TEST(ResultBytes, ATruncatedMessageIsRefused) {
  tsp::ExperimentRun r;
  r.instance = "eil51";
  r.result.best.path = {0, 1, 2};
  dist::ByteWriter out;
  write(out, r);
  const auto bytes = out.take();
  dist::ByteReader in(std::span<const std::byte>(bytes).first(bytes.size() - 1));
  EXPECT_THROW(dist::read_experiment_run(in), std::runtime_error);
}

}  // namespace
}  // namespace antslam::cli
