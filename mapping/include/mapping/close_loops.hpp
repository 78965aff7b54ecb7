#pragma once
// Closing the loops with every trusted closure. A bounded loss (eq. 10, or a robust kernel)
// cannot tell a real closure far from a drifted map from a false one: both sit where its terms
// are flat, so the optimizer gives them up. Which closures to trust is decided instead by their
// consistency with each other and with the alignments: least squares over the alignments and
// the trusted closures (Ceres), then the closure that agrees worst with that joint solution is
// distrusted if its squared Mahalanobis distance exceeds the chi-square quantile (3 dof), and
// the rest are solved again, until every trusted closure passes (iterative outlier rejection, a
// joint consistency test in place of pairwise consistency with a maximum clique, PCM). The map
// is the least-squares solution over the trusted closures: none is given up for being far.

#include <cstddef>
#include <span>
#include <vector>

#include "slamgraph/ceres_baseline.hpp"
#include "slamgraph/fragment_set.hpp"

namespace antslam::mapping {

struct ClosingSettings {
  bool enabled = true;           ///< close the loops after the optimizer's trials
  double outlier_chi2 = 11.345;  ///< squared Mahalanobis distance a trusted closure passes:
                                 ///< chi-square, 3 dof, 99 %
  slam::CeresSettings ceres;     ///< every least-squares solve
};

/// Throws std::invalid_argument naming the first nonsensical field.
void validate(const ClosingSettings& settings);

struct Closing {
  std::vector<bool> trusted;        ///< per closure of the set, in order
  std::vector<slam::Pose2> frames;  ///< F_1..F_N: least squares over alignments and trusted
                                    ///< closures (the means' chain if none is trusted)
  std::size_t solves = 0;           ///< least-squares solves (count)
};

/// Closes the loops of `set` from the world frames `start` (F_1..F_N, e.g. the best trial's).
/// Throws std::invalid_argument for a wrong number of frames or invalid settings,
/// std::runtime_error if Ceres fails.
Closing close_loops(const slam::FragmentSet& set, std::span<const slam::Pose2> start,
                    const ClosingSettings& settings = {});

}  // namespace antslam::mapping
