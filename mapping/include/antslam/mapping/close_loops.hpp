#pragma once
// Closing the loops with every trusted closure. A bounded loss (eq. 10, or a robust kernel)
// cannot tell a real closure far from a drifted map from a false one: both sit where its terms
// are flat, so the optimizer gives them up. Which closures to trust is decided instead by their
// consistency with each other and with the alignments: least squares over the alignments and
// the trusted closures (Ceres), then the closure that agrees worst with that joint solution is
// distrusted if its squared Mahalanobis distance exceeds the chi-square quantile (3 dof), and
// the rest are solved again, until every trusted closure passes (iterative outlier rejection,
// `iterative-chi2`, the default). Or the trusted closures are a maximum clique of pairwise
// consistent closures (PCM, Mangelson et al. 2018; slamgraph/consistency.hpp on the fragment
// set: its alignments are the chain), found by branch and bound (`pcm-exact`) or by the ants
// (`pcm-aco`), and the same iterative rejection then checks the clique jointly (without it,
// pcm.check_clique false, one least-squares solve over the clique: PCM as published). The map
// is the least-squares solution over the trusted closures: none is given up for being far.

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "antslam/slamgraph/ceres_baseline.hpp"
#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/robust.hpp"

namespace antslam::mapping {

/// How the closures to trust are chosen.
enum class ClosureSelection { iterative_chi2, pcm_exact, pcm_aco };

struct ClosureSelectionInfo {
  ClosureSelection value;
  std::string_view name;     ///< the name options and reports use
  std::string_view summary;  ///< one line for help texts
};

inline constexpr std::array<ClosureSelectionInfo, 3> kClosureSelections{{
    {ClosureSelection::iterative_chi2, "iterative-chi2",
     "distrust the worst closure of the joint solution until all pass chi2"},
    {ClosureSelection::pcm_exact, "pcm-exact",
     "PCM maximum clique by branch and bound, then the iterative chi2 check on it"},
    {ClosureSelection::pcm_aco, "pcm-aco",
     "PCM maximum clique by the ants, then the iterative chi2 check on it"},
}};

std::string_view to_string(ClosureSelection selection);
std::optional<ClosureSelection> parse_closure_selection(std::string_view name);

struct ClosingSettings {
  bool enabled = true;  ///< close the loops after the optimizer's trials
  ClosureSelection selection = ClosureSelection::iterative_chi2;  ///< which closures to trust
  double outlier_chi2 = 11.345;  ///< squared Mahalanobis distance a trusted closure passes:
                                 ///< chi-square, 3 dof, 99 %
  slam::CeresSettings ceres;     ///< every least-squares solve
  slam::RobustSettings pcm;      ///< pcm-*: the consistency test's confidence (0.99), the clique
                                 ///< searches, backend, threads and check_clique (its Ceres and
                                 ///< DCS settings unused)
};

/// Throws std::invalid_argument naming the first nonsensical field.
void validate(const ClosingSettings& settings);

struct Closing {
  std::vector<bool> trusted;        ///< per closure of the set, in order
  std::vector<slam::Pose2> frames;  ///< F_1..F_N: least squares over alignments and trusted
                                    ///< closures (the means' chain if none is trusted)
  std::size_t solves = 0;           ///< least-squares solves (count)
  std::optional<slam::CliqueReport> clique;  ///< pcm-*: the consistency graph's maximum clique
};

/// Closes the loops of `set` from the world frames `start` (F_1..F_N, e.g. the best trial's).
/// Throws std::invalid_argument for a wrong number of frames or invalid settings,
/// std::runtime_error if Ceres fails.
Closing close_loops(const slam::FragmentSet& set, std::span<const slam::Pose2> start,
                    const ClosingSettings& settings = {});

}  // namespace antslam::mapping
