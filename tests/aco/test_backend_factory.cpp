// Backends and variants by name: the tables round-trip, automatic resolves as documented, the
// factory builds what it is asked for, and RunResult records what ran.

#include <gtest/gtest.h>

#include <atomic>
#include <set>
#include <stdexcept>
#include <string>

#include "antslam/aco/backend_factory.hpp"
#include "antslam/aco/synthetic_layered.hpp"
#include "antslam/aco/variants.hpp"

namespace antslam::aco {
namespace {

TEST(BackendKind, NamesRoundTrip) {
  std::set<std::string> seen;
  for (const BackendInfo& b : kBackends) {
    EXPECT_EQ(parse_backend(b.name), b.kind);
    EXPECT_EQ(to_string(b.kind), b.name);
    EXPECT_TRUE(seen.insert(std::string(b.name)).second);
  }
  EXPECT_EQ(parse_backend("openmp"), std::nullopt);
  EXPECT_EQ(backend_names(), "auto, serial, omp, tbb");
}

TEST(BackendKind, AutomaticIsSerialOnOneThreadAndTbbOtherwise) {
  EXPECT_EQ(resolve(BackendKind::automatic, 1), BackendKind::serial);
  EXPECT_EQ(resolve(BackendKind::automatic, 2), BackendKind::tbb);
  EXPECT_EQ(resolve(BackendKind::automatic, 0), BackendKind::tbb);  // all cores
  EXPECT_EQ(resolve(BackendKind::omp, 1), BackendKind::omp);
  EXPECT_EQ(resolve(BackendKind::serial, 1), BackendKind::serial);
  EXPECT_THROW(resolve(BackendKind::serial, 2), std::invalid_argument);
  EXPECT_THROW(resolve(BackendKind::serial, 0), std::invalid_argument);
}

TEST(BackendFactory, BuildsTheNamedBackendWithItsThreads) {
  for (const auto& [kind, threads] :
       {std::pair{BackendKind::serial, std::size_t{1}}, std::pair{BackendKind::omp, std::size_t{3}},
        std::pair{BackendKind::tbb, std::size_t{2}},
        std::pair{BackendKind::automatic, std::size_t{2}}}) {
    AnyBackend b = make_backend(kind, threads);
    EXPECT_EQ(b.kind(), resolve(kind, threads));
    EXPECT_EQ(b.threads(), threads);
    std::atomic<int> sum = 0;  // every index exactly once
    b.for_each(100, [&](std::size_t i) { sum += static_cast<int>(i); });
    EXPECT_EQ(sum.load(), 4950);
  }
}

TEST(BackendFactory, WithBackendPassesTheConcreteType) {
  const bool serial = with_backend(
      BackendKind::automatic, 1, [](auto b) { return std::is_same_v<decltype(b), SerialBackend>; });
  const bool tbb = with_backend(BackendKind::automatic, 2,
                                [](auto b) { return std::is_same_v<decltype(b), TbbBackend>; });
  EXPECT_TRUE(serial);
  EXPECT_TRUE(tbb);
}

TEST(VariantTable, NamesRoundTripAndAreUnique) {
  std::set<std::string> seen;
  for (const VariantInfo& v : kVariants) {
    EXPECT_EQ(parse_variant(v.name), v.variant);
    EXPECT_EQ(to_string(v.variant), v.name);
    EXPECT_TRUE(seen.insert(std::string(v.name)).second);
    EXPECT_FALSE(v.summary.empty());
  }
  EXPECT_EQ(all_variants().size(), kVariants.size());
  EXPECT_EQ(variant_names().front(), "as");
  EXPECT_EQ(parse_variant("MMAS"), std::nullopt);
}

TEST(RunResult, RecordsTheSettingsThatRan) {
  const SyntheticLayeredProblem problem(4, 3, 9);
  Parameters p;
  p.variant = Variant::acs;
  p.seed = 5;
  const RunResult r = solve(problem, p, {.max_iterations = 3}, make_backend(BackendKind::tbb, 2));
  EXPECT_EQ(r.settings.variant, Variant::acs);
  EXPECT_EQ(r.settings.colony.ants, 10U);  // ACS default
  EXPECT_DOUBLE_EQ(r.settings.rho, 0.1);
  EXPECT_EQ(r.settings.colony.seed, 5U);
  EXPECT_FALSE(r.settings.local_search);
  EXPECT_EQ(r.settings.backend, BackendKind::tbb);
  EXPECT_EQ(r.settings.threads, 2U);
}

}  // namespace
}  // namespace antslam::aco
