#pragma once
// Robust back ends on a pose graph with possibly false loop closures, all started from the
// odometry chain and all ending in Ceres:
//   ls         least squares on every edge;
//   cauchy     Ceres' Cauchy loss on the closures;
//   dcs        dynamic covariance scaling on the closures (Agarwal et al. 2013);
//   gnc        graduated non-convexity with a truncated-least-squares cost (Yang et al. 2020):
//              weighted least squares whose closure weights follow the GNC-TLS rule as the
//              surrogate's parameter mu grows, from a convex start to the TLS cost, then least
//              squares on the closures it kept;
//   pcm-exact  the maximum clique of pairwise consistent closures (PCM, Mangelson et al. 2018)
//              by branch and bound, then its joint check (below), then least squares on the
//              closures that pass;
//   pcm-aco    the same with the clique found by the ants (Ant-Clique).
// The joint check (check_clique) solves DCS on the clique's closures, started from a few least-
// squares iterations on them, and keeps the clique closures whose residual then passes the
// chi-square test: the pairwise tests over long odometry spans have little power, and a clique
// can hold false closures consistent with every other one pairwise but not with the map they
// make together. Without it the PCM methods are the published PCM. Its DCS uses DCS's Phi
// (dcs_phi, at the stated noise) unless check_phi > 0: then Phi is check_phi times the median,
// over the clique's closures, of the squared Mahalanobis distance of the cycle each closes with
// the odometry (the unary test of consistency.hpp), which scales with the stated information as
// chi2 does (docs/robust-closures.md: better on generated graphs, mixed on the public ones).
// The recalibrated check follows the joint check: it measures the noise the checked graph shows,
// its trimmed variance factor f (shown_variance_factor), and when f is below recalibrate_below
// searches a second clique (the "core") with every information matrix divided by f, solves least
// squares on the closures both cliques hold, then DCS on the closures either holds from that
// map, and accepts those whose residual passes the test at the recalibrated noise (chi2 <= f c2).
// Graphs that state their noise wider than it is give the pairwise test little power; at the
// noise they show, a false closure that agrees with the odometry over a long span rarely agrees
// with the core. On graphs that state their noise as it is, or up to about 2.5 times as wide, it
// costs recall and moves the map (docs/robust-closures.md: the threshold was chosen on
// generated graphs).
// At the shown noise (shown_noise, off by default) the PCM methods first estimate the noise the
// graph shows per axis (shown_noise.hpp) and decide everything at it: the pairwise tests, the
// check and the final solve run on the graph with every covariance at that scale; since the
// tests are then sharp, each runs at the family-wise confidence (pairwise_confidence), so that a
// true closure survives all its m - 1 pairwise tests and the check with the inlier confidence,
// and a cycle whose heading deviation exceeds kLinearHeadingSd is tested on its heading alone
// (consistency.hpp). On generated graphs it keeps every true closure whichever way the graph
// misstates its noise; where short cycles show less noise than long ones, or false closures
// state theirs apart from the graph's, it fails (docs/robust-closures.md).
// By default (widen_noise) the PCM methods estimate that noise too, and where an axis is stated
// narrower than shown (a scale above kWidenAbove) they decide on the graph with that axis widened
// to the noise shown, each test at the inlier confidence as at the stated noise; an axis stated
// wider is left to the recalibrated check. Widening only, since a graph's short cycles can show
// far less noise than its long ones (ring: a 60th of its stated heading noise), and narrowing
// to them drops true closures; the false closures that a widened graph lets in are those that
// state their own noise wider than the graph's (the Vertigo generator's), and on a small graph
// with far more false closures than true ones the estimate is theirs (docs/robust-closures.md).
// Odometry (edges between consecutive vertices) is always kept with the squared loss. A closure
// counts as accepted by ls (every closure), by cauchy and dcs when its final residual passes the
// chi-square test of `inlier_confidence`, by gnc when its final weight is above 1/2, and by the
// PCM methods when it is in the clique (and passes the joint check).

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "antslam/aco/backend_kind.hpp"
#include "antslam/clique/aco_search.hpp"
#include "antslam/clique/exact.hpp"
#include "antslam/slamgraph/ceres_baseline.hpp"
#include "antslam/slamgraph/chain.hpp"
#include "antslam/slamgraph/consistency.hpp"
#include "antslam/slamgraph/g2o.hpp"
#include "antslam/slamgraph/shown_noise.hpp"

namespace antslam::slam {

enum class RobustMethod { ls, cauchy, dcs, gnc, pcm_exact, pcm_aco };

struct RobustMethodInfo {
  RobustMethod value;
  std::string_view name;     ///< the name options and files use
  std::string_view summary;  ///< one line for help texts
};

inline constexpr std::array<RobustMethodInfo, 6> kRobustMethods{{
    {RobustMethod::ls, "ls", "least squares on every edge"},
    {RobustMethod::cauchy, "cauchy", "Cauchy loss on the loop closures"},
    {RobustMethod::dcs, "dcs", "dynamic covariance scaling (Agarwal et al. 2013)"},
    {RobustMethod::gnc, "gnc",
     "graduated non-convexity, truncated least squares (Yang et al. 2020)"},
    {RobustMethod::pcm_exact, "pcm-exact",
     "PCM maximum clique by branch and bound, its joint check, then ls"},
    {RobustMethod::pcm_aco, "pcm-aco", "PCM maximum clique by the ants, its joint check, then ls"},
}};

std::string_view to_string(RobustMethod method);
std::optional<RobustMethod> parse_robust_method(std::string_view name);

struct GncSettings {
  double mu_factor = 1.4;          ///< mu grows by this factor per step (Yang et al. 2020)
  std::size_t max_steps = 1000;    ///< graduation steps at most (count)
  double weight_tolerance = 1e-6;  ///< weights this close to 0 or 1 count as decided
  int step_iterations = 10;        ///< Levenberg-Marquardt iterations per step (count), each
                                   ///< step warm-started from the last; the final solve on the
                                   ///< kept closures runs to convergence (RobustSettings::ceres)
};

/// A shown-noise scale (shown_noise.hpp) above this widens its axis (RobustSettings::widen_noise):
/// on generated graphs stating their noise as it is, the estimate lies between 1.0 and 1.2.
inline constexpr double kWidenAbove = 1.25;

struct RobustSettings {
  double inlier_confidence = 0.99;  ///< chi-square (3 dof) probability: the PCM threshold, the
                                    ///< GNC truncation c^2 and the acceptance test of cauchy/dcs
  double cauchy_scale = 1.0;        ///< c of the Cauchy loss, chi units (Ceres' CauchyLoss(1))
  double dcs_phi = 1.0;             ///< Phi of DCS, chi^2 units (Agarwal et al. 2013 use 1)
  bool shown_noise = false;         ///< pcm-*: decide at the noise the graph shows, per axis
                                    ///< (shown_noise.hpp), with family-wise confidences (above)
  bool check_clique = true;         ///< pcm-*: the joint check of the clique (above)
  double check_phi = 0.0;           ///< pcm-*: Phi of the check's DCS, in multiples of the
                                    ///< clique's median unary distance (above); 0: dcs_phi
  int check_start_iterations = 10;  ///< pcm-*: least-squares iterations that start the check
  double recalibrate_below = 0.13;  ///< pcm-*: the recalibrated check (above) runs when the
                                    ///< noise the checked graph shows (its variance factor) is
                                    ///< below this: a graph stating its noise over 2.8 times as
                                    ///< wide (standard deviation) as it shows; 0: never,
                                    ///< infinity: always
  bool widen_noise = true;          ///< pcm-*: an axis the graph states narrower than its
                            ///< short cycles show (a scale over kWidenAbove; shown_noise.hpp)
                            ///< is decided at the noise they show
  std::size_t prune_from = 4000;  ///< pcm-*: closures (count) from which the clique search
                                  ///< sees only what the pruning leaves (clique/reduction.hpp);
                                  ///< below, the whole graph (the same clique as before the
                                  ///< pruning existed; it may pick another of equal size)
  GncSettings gnc;                ///< graduated non-convexity
  clique::ExactSettings exact;    ///< pcm-exact: branch and bound (60 s budget)
  clique::AcoSearchSettings aco;  ///< pcm-aco: variant, ants, termination; its backend and
                                  ///< threads are those below (others are refused)
  CeresSettings ceres;            ///< every Ceres solve
  aco::BackendKind backend = aco::BackendKind::automatic;  ///< consistency pairs and ants
  std::size_t threads = 1;                                 ///< their threads; 0 = all cores
};

/// The maximum-clique stage of the PCM methods.
struct CliqueReport {
  std::size_t consistent_pairs = 0;  ///< edges of the consistency graph
  clique::CliqueResult clique;       ///< the trusted closures (indices into split.closures)
  std::uint64_t work = 0;            ///< branch-and-bound nodes (exact) or colony iterations
  std::size_t searched = 0;          ///< closures the search saw, after the pruning
};

struct RobustResult {
  RobustMethod method = RobustMethod::ls;  ///< what ran
  ChainSplit split;                        ///< the graph's chain and closures
  std::vector<Pose2> poses;                ///< optimised vertex poses
  std::vector<bool> accepted;              ///< per loop closure, in split.closures order
  std::optional<ShownNoise> shown_noise;   ///< PCM methods: the noise the graph shows
  std::optional<CliqueReport> clique;      ///< PCM methods only
  std::optional<double> check_phi;         ///< joint check: the Phi of its DCS
  std::optional<double> variance_factor;   ///< joint check: the checked graph's factor f
  std::optional<NoiseScale> widened;       ///< PCM methods: the scale decided at, when an
                                           ///< axis was widened (RobustSettings::widen_noise)
  std::optional<CliqueReport> core;        ///< recalibrated check (f below the threshold): the
                                           ///< clique at the noise / f
  std::size_t gnc_steps = 0;               ///< gnc only: graduation steps run
  double consistency_s = 0.0;              ///< wall-clock seconds: pairwise consistency
  double clique_s = 0.0;                   ///< maximum clique
  double optimize_s = 0.0;                 ///< Ceres solves (all of them)
  double total_s = 0.0;                    ///< the whole call
};

/// The confidence of each pairwise test among `closures` closures such that a true closure
/// passes all its closures - 1 tests with probability `confidence` (Bonferroni: the clique keeps
/// a closure only if it passes every test, so at a per-test confidence a graph of a thousand true
/// closures would lose a tenth of them to chance).
double pairwise_confidence(double confidence, std::size_t closures);

/// PCM's selection: a maximum clique of the consistency graph, by branch and bound (pcm_exact) or
/// by the ants (pcm_aco), with the clique settings, backend and threads of `settings`; what
/// solve_robust's PCM methods run, for a pose graph or a fragment set alike. Throws
/// std::invalid_argument for another method or invalid settings.
CliqueReport maximum_consistent_set(const ConsistencyGraph& consistency, RobustMethod method,
                                    const RobustSettings& settings);

/// The noise the graph shows at `poses` (the recalibrated check's f): the a posteriori variance
/// factor (chi2 / degrees of freedom, ResidualSummary) of the odometry and the closures marked
/// in `accepted` (split order), recomputed without the closures whose chi2 exceeds f c2 until
/// none does. A false closure the check kept is a gross error at the noise the others show; the
/// trimming keeps it from inflating f (on a graph without one it lowers f by a few per cent).
/// None without redundancy.
std::optional<double> shown_variance_factor(const PoseGraph& graph, const ChainSplit& split,
                                            const std::vector<bool>& accepted,
                                            std::span<const Pose2> poses, double c2);

/// Throws std::runtime_error "source: ..." for a graph whose chain is broken and
/// std::invalid_argument for invalid settings.
RobustResult solve_robust(const PoseGraph& graph, RobustMethod method,
                          const RobustSettings& settings, const std::string& source);

/// The optimised graph: the result's poses, every odometry edge and the accepted closures, in
/// input order.
PoseGraph kept_graph(const PoseGraph& graph, const RobustResult& result);

/// Accepted closures against the known false ones: precision = accepted true closures /
/// accepted closures, recall = accepted true closures / true closures (each empty when its
/// denominator is 0).
struct AcceptanceScores {
  std::size_t closures = 0;           ///< loop closures in the graph
  std::size_t accepted = 0;           ///< accepted by the method
  std::size_t outliers = 0;           ///< false closures in the graph
  std::size_t accepted_outliers = 0;  ///< false closures accepted
  std::optional<double> precision;    ///< fraction of accepted that are true
  std::optional<double> recall;       ///< fraction of true that are accepted
};
/// Throws std::invalid_argument if the two lists differ in length.
AcceptanceScores score_acceptance(const std::vector<bool>& accepted,
                                  const std::vector<bool>& outlier);

}  // namespace antslam::slam
