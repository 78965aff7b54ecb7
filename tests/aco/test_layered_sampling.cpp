// LayeredFamily's draw: the branch-free binary search returns exactly the linear count of
// cumulative entries <= u, for every table size, with ties, zero-probability options and the
// infinite tail that prepare() writes.

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "antslam/aco/layered_family.hpp"
#include "antslam/aco/random.hpp"
#include "antslam/aco/synthetic_layered.hpp"

namespace antslam::aco {
namespace {

using Family = LayeredFamily<SyntheticLayeredProblem>;

std::uint32_t linear_count(const std::vector<double>& cdf, double u) {
  std::uint32_t below = 0;
  for (double c : cdf) below += c <= u ? 1U : 0U;
  return below;
}

TEST(LayeredSampling, BinarySearchEqualsLinearCount) {
  Rng rng(42);
  for (std::size_t m = 1; m <= 40; ++m) {
    for (int table = 0; table < 50; ++table) {
      std::vector<double> cdf(m);
      double acc = 0.0;
      for (double& c : cdf) {
        acc += rng.uniform() < 0.3 ? 0.0 : rng.uniform();  // ties from zero probabilities
        c = acc;
      }
      for (double& c : cdf) c /= acc > 0.0 ? acc : 1.0;
      const std::size_t tail = rng.below(static_cast<std::uint32_t>(m));
      for (std::size_t o = tail; o < m; ++o) cdf[o] = std::numeric_limits<double>::infinity();
      for (int draw = 0; draw < 40; ++draw) {
        const double u = draw == 0 ? 0.0 : (draw == 1 ? cdf[0] : rng.uniform());
        ASSERT_EQ(Family::count_at_most(cdf.data(), m, u), linear_count(cdf, u))
            << "m = " << m << ", u = " << u;
      }
    }
  }
}

}  // namespace
}  // namespace antslam::aco
