// TSP experiments: the runs come in the documented order with the seeds and thread counts asked
// for, a run's result does not depend on its thread count, a run stops at a known optimum, and
// the CSV and Markdown reports hold every run and one row per group.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stop_token>
#include <string>
#include <vector>

#include "antslam/tsp/experiment.hpp"

namespace antslam::tsp {
namespace {

const std::filesystem::path kFixtures = ANTSLAM_FIXTURE_DIR;

ExperimentSettings small_experiment() {
  ExperimentSettings e;
  e.instances = {kFixtures / "burma14.tsp"};
  e.variants = {aco::Variant::mmas, aco::Variant::acs};
  e.threads = {1, 2};
  e.seeds = 2;
  e.first_seed = 7;
  e.solver.local_search.kind = LocalSearchKind::none;
  e.solver.backend = aco::BackendKind::tbb;
  e.termination.max_iterations = 15;
  return e;
}

TEST(Experiment, RunsInOrderAndThreadsDoNotChangeAResult) {
  std::size_t reports = 0, last_total = 0;
  const std::vector<ExperimentRun> runs =
      run_experiment(small_experiment(), [&](std::size_t index, std::size_t total,
                                             const ExperimentRun& r, const aco::IterationReport&) {
        EXPECT_LT(index, total);
        EXPECT_EQ(r.instance, "burma14");
        last_total = total;
        ++reports;
      });
  ASSERT_EQ(runs.size(), 8U);
  EXPECT_EQ(last_total, 8U);
  EXPECT_EQ(reports, 8U * 15U);
  std::size_t k = 0;
  for (const aco::Variant v : {aco::Variant::mmas, aco::Variant::acs})
    for (const std::size_t threads : {1U, 2U})
      for (const std::uint64_t seed : {7U, 8U}) {
        const ExperimentRun& r = runs[k++];
        EXPECT_EQ(r.variant, v);
        EXPECT_EQ(r.threads, threads);
        EXPECT_EQ(r.seed, seed);
        EXPECT_EQ(r.cities, 14U);
        EXPECT_EQ(r.result.iterations, 15U);
        EXPECT_EQ(r.result.settings.threads, threads);
        EXPECT_FALSE(r.optimum.has_value());
        EXPECT_TRUE(std::isnan(r.excess_percent()));
      }
  for (std::size_t i = 0; i < runs.size(); i += 4)
    for (std::size_t s = 0; s < 2; ++s) {
      EXPECT_EQ(runs[i + s].length, runs[i + 2 + s].length);  // threads 1 and 2, same seed
      EXPECT_EQ(runs[i + s].result.best.path, runs[i + 2 + s].result.best.path);
    }
}

TEST(Experiment, StopsAtTheKnownOptimumAndReportsIt) {
  const std::filesystem::path dir = std::filesystem::path(ANTSLAM_TEST_TMP) / "experiment";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(kFixtures / "burma14.tsp", dir / "burma14.tsp",
                             std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "optima.csv") << "instance,n,edge_weight_type,optimal_length\n"
                                       "burma14,14,GEO,3323\n";
  ExperimentSettings e = small_experiment();
  e.instances = {resolve_instance("burma14", dir)};
  e.variants = {aco::Variant::mmas};
  e.threads = {1};
  e.solver.local_search.kind = LocalSearchKind::two_opt;
  e.termination.max_iterations = 500;
  const std::vector<ExperimentRun> runs = run_experiment(e);
  ASSERT_EQ(runs.size(), 2U);
  for (const ExperimentRun& r : runs) {
    EXPECT_EQ(r.optimum, 3323.0);
    EXPECT_TRUE(r.hit_optimum());
    EXPECT_EQ(r.excess_percent(), 0.0);
    EXPECT_EQ(r.result.reason, aco::StopReason::target);
    EXPECT_LT(r.result.iterations, 500U);
  }
  std::ostringstream csv, md;
  write_runs_csv(csv, runs, "2opt");
  write_summary_markdown(md, runs, "2opt");
  EXPECT_NE(csv.str().find("\nburma14,14,mmas,2opt,1,7,3323,3323,0,1,"), std::string::npos)
      << csv.str();
  EXPECT_NE(md.str().find("| burma14 | 14 | mmas | 2opt | 1 | 2 | 3323 | 3323.0 | 3323 | 0.000 | "
                          "2/2 |"),
            std::string::npos)
      << md.str();
}

TEST(Experiment, ASubsetOfRunsGivesTheSameRunsInTheOrderAsked) {
  ExperimentSettings e = small_experiment();
  e.instances.push_back(kFixtures / "burma14.tsp");  // 16 runs, the second 8 on a second instance
  e.termination.max_iterations = 4;
  ASSERT_EQ(run_count(e), 16U);
  const std::vector<ExperimentRun> all = run_experiment(e);
  e.only = {{13, 2, 7}};
  const std::vector<ExperimentRun> some = run_experiment(e);
  ASSERT_EQ(some.size(), 3U);
  const std::size_t order[] = {13, 2, 7};
  for (std::size_t k = 0; k < 3; ++k) {
    const ExperimentRun& a = all[order[k]];
    EXPECT_EQ(some[k].variant, a.variant);
    EXPECT_EQ(some[k].threads, a.threads);
    EXPECT_EQ(some[k].seed, a.seed);
    EXPECT_EQ(some[k].length, a.length);
    EXPECT_EQ(some[k].result.best.path, a.result.best.path);
  }
  EXPECT_EQ(some[0].seed, 8U);  // 13 = ((1 * 2 + 1) * 2 + 0) * 2 + 1: acs, 1 thread, seed 7 + 1
  EXPECT_EQ(some[0].variant, aco::Variant::acs);
  e.only = {{16}};
  EXPECT_THROW(run_experiment(e), std::invalid_argument);
}

TEST(Experiment, AStopKeepsTheFinishedRunsAsTheyWouldHaveEnded) {
  ExperimentSettings e = small_experiment();
  e.termination.max_iterations = 200;  // a run cut short is left out, not ended by its budget
  e.only = {{5, 2}};
  const std::vector<ExperimentRun> uninterrupted = run_experiment(e);
  std::stop_source stop;
  e.termination.stop = stop.get_token();
  e.only = {{5, 2, 3, 1}};  // run in this order
  const std::vector<ExperimentRun> some =
      run_experiment(e, [&](std::size_t index, std::size_t, const ExperimentRun&,
                            const aco::IterationReport& report) {
        if (index == 3 && report.iteration == 1) stop.request_stop();
      });
  ASSERT_EQ(some.size(), 2U);  // 5 and 2 finished, 3 cut short, 1 never started
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(some[k].seed, uninterrupted[k].seed);
    EXPECT_EQ(some[k].threads, uninterrupted[k].threads);
    EXPECT_EQ(some[k].variant, uninterrupted[k].variant);
    EXPECT_EQ(some[k].result.best.path, uninterrupted[k].result.best.path);
    EXPECT_EQ(some[k].result.iterations, 200U);
  }
  e.only.reset();
  EXPECT_TRUE(run_experiment(e).empty());  // stopped already: the first run is cut short
}

TEST(Experiment, AStopAfterARunEndsKeepsIt) {
  ExperimentSettings e = small_experiment();
  const std::vector<ExperimentRun> all = run_experiment(e);
  std::stop_source stop;
  e.termination.stop = stop.get_token();
  const std::vector<ExperimentRun> some =
      run_experiment(e, [&](std::size_t index, std::size_t, const ExperimentRun&,
                            const aco::IterationReport& report) {
        if (index == 1 && report.iteration == 15) stop.request_stop();  // its last iteration
      });
  ASSERT_EQ(some.size(), 2U);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(some[k].result.best.path, all[k].result.best.path);
    EXPECT_EQ(some[k].result.reason, aco::StopReason::iterations);
  }
}

TEST(Experiment, ReportsHaveARowPerRunAndPerGroup) {
  ExperimentSettings e = small_experiment();
  e.termination.max_iterations = 3;
  const std::vector<ExperimentRun> runs = run_experiment(e);
  std::ostringstream csv, md;
  write_runs_csv(csv, runs, "none");
  write_summary_markdown(md, runs, "none");
  const auto lines = [](const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  };
  EXPECT_EQ(lines(csv.str()), 1U + 8U);
  EXPECT_EQ(lines(md.str()), 2U + 4U);  // header, rule, (mmas, acs) x (1, 2 threads)
  EXPECT_NE(md.str().find("| - | - |"), std::string::npos);  // no known optimum
}

TEST(Experiment, RejectsAnUnboundedBudgetAndSerialOnTwoThreads) {
  ExperimentSettings e = small_experiment();
  e.termination.max_iterations = 0;
  EXPECT_THROW(validate(e), std::invalid_argument);
  e = small_experiment();
  e.solver.backend = aco::BackendKind::serial;
  EXPECT_THROW(run_experiment(e), std::invalid_argument);
  e.seeds = 0;
  EXPECT_THROW(validate(e), std::invalid_argument);
  EXPECT_THROW(resolve_instance("no-such-instance", kFixtures), std::runtime_error);
}

}  // namespace
}  // namespace antslam::tsp
