#pragma once
// The colony's contract, checked for one problem at a time in the style of manif's MANIF_TEST:
//   ANTSLAM_COLONY_CONTRACT(Name, Fixture)
// instantiates, for every variant of the engine's table x every backend and thread count, a run
// of the real dispatch (aco::with_colony) that checks after every iteration that each ant's path
// is feasible and its reported cost equals a fresh evaluation, that the best is no worse than
// any ant, and that pheromone stays within the variant's bounds; and that best cost, best path
// and final trail are bit-identical to the serial run.
//
// A Fixture is default-constructible and offers
//   const Problem& problem() const;
//   LocalSearch local_search() const;        (aco::NoLocalSearch for none)
//   bool feasible(std::span<const std::uint32_t> path) const;
//   static constexpr std::size_t kIterations;
// and optionally static void configure(aco::Parameters&) (e.g. focused construction).

#include <gtest/gtest.h>

#include <cstddef>
#include <ostream>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "antslam/aco/backend_factory.hpp"
#include "antslam/aco/variant.hpp"
#include "antslam/aco/variants.hpp"

namespace antslam::testing {

struct BackendSpec {
  aco::BackendKind kind;
  std::size_t threads;
};

/// GoogleTest prints "tbb x2".
inline void PrintTo(const BackendSpec& spec, std::ostream* os) {
  *os << aco::to_string(spec.kind) << " x" << spec.threads;
}

inline const std::vector<BackendSpec>& all_backend_specs() {
  using aco::BackendKind;
  static const std::vector<BackendSpec> specs{
      {BackendKind::serial, 1}, {BackendKind::automatic, 1}, {BackendKind::automatic, 2},
      {BackendKind::omp, 1},    {BackendKind::omp, 2},       {BackendKind::omp, 3},
      {BackendKind::omp, 4},    {BackendKind::omp, 8},       {BackendKind::tbb, 1},
      {BackendKind::tbb, 2},    {BackendKind::tbb, 3},       {BackendKind::tbb, 4},
      {BackendKind::tbb, 8}};
  return specs;
}

struct ContractOutcome {
  aco::Solution best;
  std::vector<double> trail;
};

template <class Fixture>
ContractOutcome run_checked(const Fixture& fixture, aco::Variant variant, const BackendSpec& spec) {
  aco::Parameters p;
  p.variant = variant;
  p.ants = 12;
  p.seed = 2024;
  if constexpr (requires { Fixture::configure(p); }) Fixture::configure(p);
  const auto& problem = fixture.problem();
  return aco::with_colony(
      problem, p, aco::make_backend(spec.kind, spec.threads), fixture.local_search(),
      [&](auto& colony) {
        EXPECT_EQ(colony.settings().ants, 12U);
        for (std::size_t it = 0; it < Fixture::kIterations; ++it) {
          colony.step();
          for (const aco::Solution& ant : colony.ants()) {
            EXPECT_TRUE(fixture.feasible(ant.path));
            EXPECT_EQ(ant.cost, static_cast<double>(problem.cost(ant.path)));
            EXPECT_LE(colony.best().cost, ant.cost);
          }
          const auto& trail = colony.trail();
          EXPECT_GE(trail.min_value(), 0.0);
          if constexpr (requires { colony.update().tau_min(); }) {  // MAX-MIN bounds
            EXPECT_GE(trail.min_value(), colony.update().tau_min());
            EXPECT_LE(trail.max_value(), colony.update().tau_max());
          }
          if constexpr (requires { colony.update().tau_max; }) {  // the hybrid's cap
            EXPECT_LE(trail.max_value(), colony.update().tau_max);
          }
        }
        EXPECT_TRUE(fixture.feasible(colony.best().path));
        EXPECT_EQ(colony.best().cost, static_cast<double>(problem.cost(colony.best().path)));
        const auto values = colony.trail().values();
        return ContractOutcome{colony.best(), std::vector<double>(values.begin(), values.end())};
      });
}

template <class Fixture>
class ColonyContract : public ::testing::TestWithParam<std::tuple<aco::Variant, BackendSpec>> {
 protected:
  void check() {
    const auto [variant, spec] = this->GetParam();
    const Fixture fixture;
    const ContractOutcome reference = run_checked(fixture, variant, {aco::BackendKind::serial, 1});
    const ContractOutcome outcome = run_checked(fixture, variant, spec);
    EXPECT_EQ(outcome.best.cost, reference.best.cost);
    EXPECT_EQ(outcome.best.path, reference.best.path);
    EXPECT_EQ(outcome.trail, reference.trail);
  }
};

inline std::string contract_case_name(
    const ::testing::TestParamInfo<std::tuple<aco::Variant, BackendSpec>>& info) {
  const auto& [variant, spec] = info.param;
  return std::string(aco::to_string(variant)) + "_" + std::string(aco::to_string(spec.kind)) +
         std::to_string(spec.threads);
}

}  // namespace antslam::testing

#define ANTSLAM_COLONY_CONTRACT(Name, Fixture)                                          \
  using Name##Contract = ::antslam::testing::ColonyContract<Fixture>;                   \
  TEST_P(Name##Contract, ValidAndBitIdenticalOnEveryBackend) { this->check(); }         \
  INSTANTIATE_TEST_SUITE_P(                                                             \
      AllVariantsAllBackends, Name##Contract,                                           \
      ::testing::Combine(::testing::ValuesIn(::antslam::aco::all_variants()),           \
                         ::testing::ValuesIn(::antslam::testing::all_backend_specs())), \
      ::antslam::testing::contract_case_name)
