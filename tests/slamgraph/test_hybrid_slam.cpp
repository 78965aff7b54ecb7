// The paper's hybrid (Algorithm 2) on the AntSLAM problem, iteration by iteration: every ant's
// cost is the eq. (10) weight of its samples, deposits are 1/W from all ants except every
// globBestFreq-th iteration (global best and iteration best only), pheromone stays <= tau_max,
// and the best path is the minimum weight seen (line 23's comparison, read as a minimisation).

#include <gtest/gtest.h>

#include <limits>

#include "antslam/aco/colony.hpp"
#include "antslam/aco/rules.hpp"
#include "antslam/aco/update_hybrid.hpp"
#include "antslam/aco/variants.hpp"
#include "antslam/slamgraph/slam_problem.hpp"
#include "antslam/slamgraph/synth.hpp"

namespace antslam::slam {
namespace {

using HybridColony = aco::Colony<SlamProblem, aco::UniformExploration, aco::HybridUpdate>;

TEST(HybridOnSlam, FollowsAlgorithm2WithEq10Weights) {
  const FragmentSet set = synthesize(synth_preset("paper9"));
  const SlamProblem problem(set);
  const aco::Parameters paper;  // the paper's p0, globBestFreq, tau_init, tau_max
  const aco::HybridUpdate update{.rho = 0.1,
                                 .glob_best_freq = paper.glob_best_freq,
                                 .tau_max = 300.0,
                                 .tau_init = paper.tau_init,
                                 .deposit = 100.0};
  HybridColony colony(problem, {.ants = 20, .seed = 3}, aco::UniformExploration{paper.p0}, update);
  double best_seen = std::numeric_limits<double>::infinity();
  bool capped = false;
  for (std::uint64_t it = 1; it <= 40; ++it) {
    const std::vector<double> before(colony.trail().values().begin(),
                                     colony.trail().values().end());
    colony.step();
    const auto ants = colony.ants();
    std::vector<double> expected = before;
    for (double& t : expected) t *= 1.0 - update.rho;
    const auto deposit = [&](const aco::Solution& ant) {
      const double w = path_weight(set, ant.path);  // the reference eq. (10)
      EXPECT_NEAR(ant.cost, w, 1e-12);
      for (std::size_t l = 0; l < ant.path.size(); ++l)
        expected[20 * l + ant.path[l]] += update.deposit / w;
    };
    for (const aco::Solution& ant : ants) best_seen = std::min(best_seen, ant.cost);
    if (it % 5 != 0) {
      for (const aco::Solution& ant : ants) deposit(ant);
    } else {
      deposit(colony.best());
      deposit(ants[colony.ranking()[0]]);
    }
    for (std::size_t i = 0; i < expected.size(); ++i) {
      const double tau = std::min(expected[i], update.tau_max);
      ASSERT_NEAR(colony.trail().values()[i], tau, 1e-9) << "iteration " << it;
      capped |= expected[i] > update.tau_max;
    }
    EXPECT_EQ(colony.best().cost, best_seen);
  }
  EXPECT_TRUE(capped) << colony.trail().max_value();  // tau_max was exercised
}

// The hybrid's default through aco::solve is the paper's configuration.
TEST(HybridOnSlam, DefaultsAreThePapers) {
  const aco::Parameters p;
  EXPECT_EQ(p.p0, 0.3);
  EXPECT_EQ(p.glob_best_freq, 5U);
  EXPECT_EQ(p.tau_max, 10000.0);
  EXPECT_EQ(p.tau_init, 100.0);
  EXPECT_EQ(aco::default_ants(aco::Variant::hybrid, 8, false, false), 20U);
}

}  // namespace
}  // namespace antslam::slam
