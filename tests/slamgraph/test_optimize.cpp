// optimize(): every method, its result consistent with the model, determinism across threads.

#include <gtest/gtest.h>

#include <stop_token>

#include "antslam/slamgraph/optimize.hpp"
#include "antslam/slamgraph/search_baselines.hpp"
#include "antslam/slamgraph/synth.hpp"
#include "antslam/slamgraph/trials.hpp"
#include "support.hpp"

namespace antslam::slam {
namespace {

OptimizeSettings quick(Method m, std::uint64_t seed = 1) {
  OptimizeSettings s;
  s.method = m;
  s.seed = seed;
  s.iterations = 60;
  return s;
}

TEST(Optimize, EveryMethodReturnsAConsistentResult) {
  const FragmentSet set = testing::random_set(5, 4, 2, 3);
  const double optimum = exhaustive_search(set, 1000).weight;
  for (Method m : all_methods()) {
    SCOPED_TRACE(std::string(to_string(m)));
    const OptimizeResult r = optimize(set, quick(m));
    EXPECT_EQ(r.method, m);
    ASSERT_EQ(r.alignments.size(), 4U);
    ASSERT_EQ(r.frames.size(), 5U);
    const std::vector<Pose2> frames = chain(r.alignments);
    for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(r.frames[i].x, frames[i].x);
    const Scores s = score(set, r.alignments);
    EXPECT_EQ(r.scores.weight, s.weight);
    EXPECT_EQ(r.scores.chi2, s.chi2);
    if (is_discrete(m)) {
      ASSERT_EQ(r.choice.size(), 4U);
      EXPECT_NEAR(r.scores.weight, path_weight(set, r.choice), 1e-12);
      EXPECT_GE(r.scores.weight, optimum - 1e-12);
    }
    ASSERT_FALSE(r.convergence.empty());
    for (std::size_t k = 1; k < r.convergence.size(); ++k)
      EXPECT_LT(r.convergence[k].best_weight, r.convergence[k - 1].best_weight);
    EXPECT_NEAR(r.convergence.back().best_weight, r.scores.weight, 1e-9);
    EXPECT_GE(r.elapsed_s, r.time_to_best_s);
  }
}

TEST(Optimize, ExhaustiveIsTheOptimumAndRandomUsesTheAntsBudget) {
  const FragmentSet set = testing::random_set(5, 4, 2, 3);
  EXPECT_NEAR(optimize(set, quick(Method::exhaustive)).scores.weight,
              exhaustive_search(set, 1000).weight, 1e-12);
  const OptimizeResult r = optimize(set, quick(Method::random));
  EXPECT_EQ(r.evaluations, 60U * 20U);
  EXPECT_EQ(r.iterations, 60U);
}

// NLopt refinement never worsens the ACO result it starts from (same seed: same ACO run).
TEST(Optimize, HybridPlusNloptIsNeverWorseThanHybrid) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const FragmentSet set = testing::random_set(7, 5, 1 + seed % 2, seed, 0.5);
    const OptimizeResult hybrid = optimize(set, quick(Method::hybrid, seed));
    const OptimizeResult refined = optimize(set, quick(Method::hybrid_nlopt, seed));
    EXPECT_EQ(refined.choice, hybrid.choice);
    EXPECT_LE(refined.scores.weight, hybrid.scores.weight + 1e-12);
    OptimizeSettings each = quick(Method::hybrid_nlopt, seed);
    each.refine_each_improvement = true;
    EXPECT_LE(optimize(set, each).scores.weight, refined.scores.weight + 1e-12);
  }
}

TEST(Optimize, SameResultOnOneOrTwoThreads) {
  const FragmentSet set = synthesize(synth_preset("paper9"));
  for (Method m : {Method::hybrid, Method::acs, Method::mmas, Method::random}) {
    OptimizeSettings s = quick(m, 5);
    const OptimizeResult one = optimize(set, s);
    s.threads = 2;
    const OptimizeResult two = optimize(set, s);
    EXPECT_EQ(one.choice, two.choice) << to_string(m);
    EXPECT_EQ(one.scores.weight, two.scores.weight);
  }
}

TEST(Trials, ResultsDoNotDependOnThreadsAndTrialsDiffer) {
  const FragmentSet set = synthesize(synth_preset("paper9"));
  const OptimizeSettings s = quick(Method::hybrid, 11);
  std::size_t last = 0;
  const auto one = run_trials(set, s, {.trials = 6, .threads = 1}, [&](std::size_t done) {
    EXPECT_EQ(done, last + 1);
    last = done;
  });
  const auto two = run_trials(set, s, {.trials = 6, .threads = 2});
  EXPECT_EQ(last, 6U);
  for (std::size_t t = 0; t < 6; ++t) {
    EXPECT_EQ(one[t].choice, two[t].choice);
    EXPECT_EQ(one[t].scores.weight, two[t].scores.weight);
  }
  OptimizeSettings first = s;
  first.seed = trial_seed(11, 0);
  EXPECT_EQ(optimize(set, first).choice, one[0].choice);
  EXPECT_NE(one[0].choice, one[1].choice);
}

TEST(Trials, ASubsetRunsEachTrialAsTheWholeStudyDoes) {
  const FragmentSet set = synthesize(synth_preset("paper9"));
  const OptimizeSettings s = quick(Method::hybrid, 5);
  const auto all = run_trials(set, s, {.trials = 5, .threads = 2});
  const auto some = run_trials(set, s, {.trials = 5, .threads = 1, .only = {{4, 1, 3}}});
  ASSERT_EQ(some.size(), 3U);
  const std::size_t order[] = {4, 1, 3};
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(some[k].choice, all[order[k]].choice);
    EXPECT_EQ(some[k].scores.weight, all[order[k]].scores.weight);
    EXPECT_EQ(some[k].convergence.size(), all[order[k]].convergence.size());
  }
  EXPECT_TRUE(run_trials(set, s, {.trials = 5, .only = std::vector<std::size_t>{}}).empty());
  EXPECT_THROW(run_trials(set, s, {.trials = 5, .only = {{5}}}), std::invalid_argument);
}

TEST(Trials, AStopKeepsTheTrialsFinishedInOrderBeforeIt) {
  const FragmentSet set = synthesize(synth_preset("paper9"));
  OptimizeSettings s = quick(Method::hybrid, 5);
  const auto all = run_trials(set, s, {.trials = 6, .threads = 1});
  std::stop_source stop;
  s.stop = stop.get_token();
  std::size_t calls = 0;
  const TrialRunner stop_in_trial_3 = [&](const OptimizeSettings& t, const OptimizeObserver& o) {
    ++calls;
    if (t.seed == trial_seed(5, 3)) stop.request_stop();  // trial 3 is cut short
    return optimize(set, t, o);
  };
  const auto kept = run_trials(stop_in_trial_3, s, {.trials = 6, .threads = 1});
  EXPECT_EQ(calls, 4U);  // trials 4 and 5 never start
  ASSERT_EQ(kept.size(), 3U);
  for (std::size_t t = 0; t < 3; ++t) {
    EXPECT_EQ(kept[t].choice, all[t].choice);
    EXPECT_EQ(kept[t].scores.weight, all[t].scores.weight);
  }
  // A single trial returns what it found when stopped (here at once: its first iteration).
  const auto one = run_trials(set, s, {.trials = 1, .threads = 1});
  ASSERT_EQ(one.size(), 1U);
  EXPECT_EQ(one[0].iterations, 1U);
}

TEST(Trials, Statistics) {
  const std::vector<double> v{1.0, 2.0, 4.0};
  const Statistics s = statistics(v);
  EXPECT_DOUBLE_EQ(s.mean, 7.0 / 3.0);
  EXPECT_DOUBLE_EQ(
      s.std,
      std::sqrt(((4.0 / 3) * (4.0 / 3) + (1.0 / 3) * (1.0 / 3) + (5.0 / 3) * (5.0 / 3)) / 2.0));
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 4.0);
  EXPECT_THROW(statistics({}), std::invalid_argument);
}

// A stop request before the run: the colony and random search end after their first iteration
// or round, NLopt at its first evaluation of each stage; every result is still a valid one.
TEST(Optimize, AStopRequestEndsEveryIterativeMethodEarly) {
  const FragmentSet set = testing::random_set(6, 5, 2, 9);
  std::stop_source source;
  source.request_stop();
  for (const Method m : {Method::mmas, Method::hybrid_nlopt, Method::random, Method::nlopt}) {
    SCOPED_TRACE(std::string(to_string(m)));
    OptimizeSettings s = quick(m);
    s.iterations = 100000;
    s.stop = source.get_token();
    const OptimizeResult r = optimize(set, s);
    EXPECT_LE(r.iterations, 1U);
    EXPECT_EQ(r.scores.weight, score(set, r.alignments).weight);
    if (m == Method::nlopt) {
      EXPECT_LT(r.evaluations, 20U);  // of up to 2000 per stage
    }
  }
  OptimizeSettings stopped;
  stopped.stop = source.get_token();
  EXPECT_TRUE(refine_settings(stopped).stop.stop_requested());
}

TEST(Optimize, RejectsNonsense) {
  const FragmentSet set = testing::random_set(9, 20, 1, 1);
  EXPECT_THROW(optimize(set, quick(Method::exhaustive)), std::invalid_argument);
  OptimizeSettings s = quick(Method::hybrid);
  s.iterations = 0;
  EXPECT_THROW(optimize(set, s), std::invalid_argument);
  s = quick(Method::ceres);
  s.initial.resize(3);
  EXPECT_THROW(optimize(set, s), std::invalid_argument);
  for (auto bad :
       {+[](OptimizeSettings& o) { o.aco.rho = -0.1; },
        +[](OptimizeSettings& o) { o.aco.rho = 1.5; }, +[](OptimizeSettings& o) { o.aco.p0 = 2.0; },
        +[](OptimizeSettings& o) { o.aco.q0 = -1.0; },
        +[](OptimizeSettings& o) { o.aco.glob_best_freq = 0; },
        +[](OptimizeSettings& o) { o.aco.tau_max = 1.0; },
        +[](OptimizeSettings& o) { o.time_limit_s = -1.0; }}) {
    OptimizeSettings o = quick(Method::hybrid);
    bad(o);
    EXPECT_THROW(optimize(set, o), std::invalid_argument);
  }
  EXPECT_EQ(parse_method("hybrid+nlopt"), Method::hybrid_nlopt);
  EXPECT_EQ(parse_method("ceres-robust"), Method::ceres_robust);
  EXPECT_THROW(parse_method("hybrid-nlopt"), std::invalid_argument);
}

TEST(Trials, OneTrialRunsItsAntsOnTheThreadsAndReportsConvergence) {
  const FragmentSet set = synthesize(synth_preset("paper9"));
  const OptimizeSettings s = quick(Method::hybrid, 11);
  std::size_t improvements = 0, finished = 0;
  const auto one = run_trials(
      set, s, {.trials = 1, .threads = 2, .backend = aco::BackendKind::tbb},
      [&](std::size_t done) { finished = done; }, [&](const ConvergencePoint&) { ++improvements; });
  ASSERT_EQ(one.size(), 1U);
  EXPECT_EQ(finished, 1U);
  EXPECT_EQ(improvements, one[0].convergence.size());
  EXPECT_GT(improvements, 0U);
  OptimizeSettings first = s;
  first.seed = trial_seed(11, 0);
  EXPECT_EQ(optimize(set, first).choice, one[0].choice);
  EXPECT_EQ(one[0].colony->threads, 2U);
}

}  // namespace
}  // namespace antslam::slam
