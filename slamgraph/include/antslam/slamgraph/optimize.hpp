#pragma once
// The optimizer API: one fragment set in, the corrected map out, by any method of the study
// (paper Sec. III-B and the baselines it is compared with). Every method is scored on both
// objectives (eq. 10 weight and chi2), so that neither is favoured silently.
//
//   method        what
//   as eas ras    Ant System and its elitist / rank-based forms on the tree of samples
//   acs mmas      Ant Colony System, MAX-MIN Ant System
//   hybrid        the paper's hybrid (Algorithm 2) with its parameters: the default
//   hybrid+nlopt  hybrid, then NLopt refinement of the best path (refine.hpp)
//   nlopt         NLopt refinement from the initial alignments (no ants)
//   ceres         Ceres least squares on the pose graph (ceres_baseline.hpp)
//   ceres-robust  Ceres under the loss that makes its cost the eq. (10) weight
//   random        uniform random paths at the ants' evaluation budget
//   exhaustive    exact optimum over all M^{N-1} paths (small sets only)

#include <cstdint>
#include <functional>
#include <optional>
#include <stop_token>
#include <string_view>
#include <vector>

#include "antslam/aco/backend_kind.hpp"
#include "antslam/aco/islands.hpp"
#include "antslam/aco/variants.hpp"
#include "antslam/slamgraph/ceres_baseline.hpp"
#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/refine.hpp"

namespace antslam::slam {

enum class Method {
  ant_system,
  elitist,
  rank_based,
  acs,
  mmas,
  hybrid,
  hybrid_nlopt,
  nlopt,
  ceres,
  ceres_robust,
  random,
  exhaustive,
};

std::string_view to_string(Method m);
/// Throws std::invalid_argument listing the valid names.
Method parse_method(std::string_view name);
/// All methods, in the order of the table above.
std::span<const Method> all_methods();
/// Whether the result is one sample per fragment (`choice` gives the alignments).
bool is_discrete(Method m);
/// The engine variant of an ACO method (hybrid+nlopt: hybrid), none for the others.
std::optional<aco::Variant> aco_variant(Method m);

/// The most ants per iteration validate() accepts.
inline constexpr std::size_t kMaxAnts = 100000;

struct OptimizeSettings {
  Method method = Method::hybrid;   ///< algorithm (table above)
  std::uint64_t seed = 1;           ///< seeds every random choice (overrides aco.seed)
  std::uint64_t iterations = 3000;  ///< ACO iterations (iter_max, paper Sec. IV); random: rounds
  double time_limit_s = 0.0;        ///< wall-clock budget of the whole run in seconds (ants, random
                                    ///< rounds, NLopt and Ceres share it); 0 = none
  std::size_t threads = 1;  ///< threads for the ants of one run; results do not depend on it
  aco::BackendKind backend = aco::BackendKind::automatic;  ///< runs the ants of one iteration
  aco::Parameters aco;    ///< engine parameters (ants, rho, p0, ...); variant from method
  RefineSettings refine;  ///< NLopt refinement (hybrid+nlopt, nlopt)
  bool refine_each_improvement = false;  ///< hybrid+nlopt: also refine every new global-best ant
  CeresSettings ceres;                   ///< Ceres baselines
  std::uint64_t max_exhaustive_paths = 1'000'000'000;  ///< exhaustive: refuse larger trees (count)
  std::vector<Pose2> initial;  ///< start of nlopt / ceres (N - 1 alignments); empty = means
  std::optional<aco::IslandSettings> islands;  ///< ACO methods: the island model, this process's
                                               ///< share of K colonies (aco/islands.hpp);
                                               ///< empty: one colony
  aco::Exchange exchange = aco::in_process_exchange;  ///< gathers the islands' offers (all in
                                                      ///< this process: the identity)
  std::stop_token stop{};  ///< once stop is requested (a user's Ctrl-C), the colony ends after its
                           ///< iteration, random search after its round and NLopt at its next
                           ///< evaluation (refine.stop is set from it); Ceres runs to its end
};

/// settings.refine with the stop token of `settings`.
RefineSettings refine_settings(const OptimizeSettings& settings);

/// The best weight found so far, reported whenever it improves.
struct ConvergencePoint {
  std::uint64_t iteration = 0;    ///< ACO iteration / random round / 0 for one-shot methods
  std::uint64_t evaluations = 0;  ///< objective evaluations so far (count)
  double elapsed_s = 0.0;         ///< wall-clock seconds since the start
  double best_weight = 0.0;       ///< eq. (10)
};
using OptimizeObserver = std::function<void(const ConvergencePoint&)>;

struct OptimizeResult {
  Method method = Method::hybrid;     ///< what produced it
  Scores scores;                      ///< eq. (10) weight and chi2 of the result
  std::vector<std::uint32_t> choice;  ///< chosen samples (discrete methods and hybrid+nlopt's
                                      ///< start); empty otherwise
  std::vector<Pose2> alignments;      ///< X_2..X_N of the result
  std::vector<Pose2> frames;          ///< world poses of F_1..F_N (eq. 8 of the alignments)
  std::uint64_t iterations = 0;       ///< ACO iterations / random rounds / solver iterations
  std::uint64_t evaluations = 0;      ///< paths or NLopt evaluations (count)
  double elapsed_s = 0.0;             ///< wall-clock seconds of the whole method
  double time_to_best_s = 0.0;        ///< wall-clock seconds until the result was found
  std::vector<ConvergencePoint> convergence;  ///< one point per improvement
  std::optional<aco::RunSettings> colony;     ///< ACO methods: the engine settings that ran
};

/// Throws std::invalid_argument naming the first nonsensical field (engine, NLopt, Ceres); the
/// checks that need no fragment set, so that a pipeline can run them before building one.
void validate(const OptimizeSettings& settings);

/// Runs settings.method on the set. Throws std::invalid_argument naming the problem for an
/// invalid set or settings (and for exhaustive search on too large a tree).
OptimizeResult optimize(const FragmentSet& set, const OptimizeSettings& settings,
                        const OptimizeObserver& observer = {});

}  // namespace antslam::slam
