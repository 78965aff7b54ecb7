#pragma once
// The colony loop (Algorithm 1 of the paper): construct the ants of an iteration in parallel,
// improve them by local search, update the pheromone, observe, check termination. Every variant
// is this one loop with different policies:
//   Rule         construction rule (rules.hpp)
//   Update       pheromone update (update_*.hpp)
//   LocalSearch  optional improvement of each ant (local_search.hpp)
//   Backend      how the ants of one iteration are spread over threads (backend*.hpp)
// Determinism: ant a of iteration t draws only from ant_stream(seed, t, a), writes only its own
// slot, and everything after construction (ranking, best, deposits) runs in ant order, so the
// result is bit-identical for every backend and thread count.

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <numeric>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "antslam/aco/backend.hpp"
#include "antslam/aco/backend_kind.hpp"
#include "antslam/aco/family.hpp"
#include "antslam/aco/focused_construction.hpp"
#include "antslam/aco/layered_family.hpp"
#include "antslam/aco/local_search.hpp"
#include "antslam/aco/permutation_family.hpp"
#include "antslam/aco/problem.hpp"
#include "antslam/aco/random.hpp"
#include "antslam/aco/solution.hpp"
#include "antslam/aco/subset_family.hpp"
#include "antslam/aco/termination.hpp"
#include "antslam/aco/update_context.hpp"
#include "antslam/aco/variant.hpp"

namespace antslam::aco {

struct ColonySettings {
  std::size_t ants = 20;   ///< ants per iteration (A of Algorithm 2)
  double alpha = 1.0;      ///< pheromone exponent of eq. (1)
  double beta = 2.0;       ///< heuristic exponent of eq. (1); no effect without heuristic
  std::uint64_t seed = 1;  ///< seed of every random stream of the run
  std::size_t local_search_ants = 0;  ///< 0: local search improves every ant; k: the k best only
  FocusedSettings focused{};  ///< ants change a source tour (permutation problems); off by default
};

/// What the observer hears after every iteration.
struct IterationReport {
  std::uint64_t iteration = 0;                      ///< 1-based
  double elapsed_s = 0.0;                           ///< wall-clock seconds since the run started
  double iteration_best = 0.0;                      ///< best cost of this iteration
  double global_best = 0.0;                         ///< best cost so far
  bool improved = false;                            ///< this iteration found a new global best
  std::span<const std::uint32_t> global_best_path;  ///< the best path so far (valid during the
                                                    ///< observer's call only)
};
using Observer = std::function<void(const IterationReport&)>;

/// The settings a run actually used, every default resolved.
struct RunSettings {
  std::optional<Variant> variant;  ///< set by solve(); empty for a colony assembled by hand
  double rho = 0.0;                ///< evaporation rate; set by solve(), 0 for a hand-built colony
  ColonySettings colony;           ///< ants, alpha, beta, seed, local-search ants
  bool local_search = false;       ///< whether a local search improved the ants
  BackendKind backend = BackendKind::serial;  ///< the backend that ran the ants
  std::size_t threads = 1;                    ///< its thread count
};

struct RunResult {
  Solution best;                     ///< best solution found
  std::uint64_t iterations = 0;      ///< iterations run
  std::uint64_t best_iteration = 0;  ///< iteration that found `best`
  double elapsed_s = 0.0;            ///< wall-clock seconds of the run
  double time_to_best_s = 0.0;       ///< wall-clock seconds until `best` was found
  StopReason reason = StopReason::iterations;
  RunSettings settings;  ///< what ran
};

template <class Problem, class Rule, class Update, class LocalSearch = NoLocalSearch,
          class Exec = SerialBackend>
requires Backend<Exec>
class Colony {
  static_assert(HasFamily<Problem>,
                "aco::Colony: no family for this problem: satisfy LayeredProblem, "
                "PermutationProblem or SubsetProblem (problem.hpp), or specialise "
                "aco::family_of<Problem> with a family of your own (family.hpp)");
  static_assert(!HasFamily<Problem> || FamilyOfProblem<Problem>,
                "aco::Colony: family_of<Problem>::type lacks a member of aco::FamilyFor "
                "(family.hpp)");

 public:
  using Family = family_t<Problem>;
  using Trail = typename Family::Trail;
  static constexpr bool kHasLocalSearch = !std::is_same_v<LocalSearch, NoLocalSearch>;
  static constexpr bool kCanFocus = requires(Family & f, std::span<const std::uint32_t> tour) {
    f.set_source(tour, std::size_t{1});
  };
  static constexpr bool kLocalSearchFromCities = LocalSearchFromCities<LocalSearch, Problem>;

  Colony(const Problem& problem, const ColonySettings& settings, Rule rule = {}, Update update = {},
         LocalSearch local_search = {}, Exec backend = {})
      : problem_(&problem),
        settings_(settings),
        rule_(std::move(rule)),
        update_(std::move(update)),
        local_search_(std::move(local_search)),
        backend_(std::move(backend)),
        family_(problem, settings.alpha, settings.beta) {
    if (settings_.ants == 0) throw std::invalid_argument("colony needs at least one ant");
    if (settings_.focused.enabled() && !kCanFocus)
      throw std::invalid_argument("focused construction needs a permutation problem");
    const std::size_t ants = settings_.ants;
    ants_.resize(ants);
    skipped_.assign(ants, 0);
    rngs_.resize(ants);
    ranking_.resize(ants);
    family_.reserve_ants(ants);
    if constexpr (kHasLocalSearch) {
      workspaces_.reserve(ants);
      for (std::size_t a = 0; a < ants; ++a)
        workspaces_.push_back(local_search_.make_workspace(problem));
    }
    reset();
  }

  /// Back to iteration 0: initial trails (Algorithm 2, lines 2-7), no best solution.
  void reset() {
    iteration_ = 0;
    best_ = Solution{};
    InitContext context = family_.init_context(settings_.ants, kHasLocalSearch);
    context.focused = settings_.focused.enabled();
    if constexpr (kCanFocus) family_.set_source({}, 0);
    update_.initialize(family_.trail(), context);
  }

  /// One iteration (Algorithm 2, lines 9-34). `stop` lets a long phase end early, so that a
  /// budget holds inside an iteration: the local search stops improving, a family that polls
  /// the token (set_stop) finishes the path it builds at once, and ants not begun when it
  /// expires are not built -- they repeat ant 0's path (ant 0 always runs, so the iteration has
  /// a best; the run ends after such an iteration, so it does not update the trail).
  IterationReport step(const StopToken& stop = {}) {
    ++iteration_;
    const std::size_t ants = settings_.ants;
    for (std::size_t a = 0; a < ants; ++a) rngs_[a] = ant_stream(settings_.seed, iteration_, a);
    if constexpr (kCanFocus) choose_source();
    if constexpr (requires { family_.set_stop(stop); }) family_.set_stop(stop);
    if constexpr (requires { family_.prepare(rule_, backend_); }) {
      family_.prepare(rule_, backend_);
    } else {
      family_.prepare(rule_);
    }

    const bool improve_all = kHasLocalSearch && (settings_.local_search_ants == 0 ||
                                                 settings_.local_search_ants >= ants);
    const auto finish = [&](std::size_t a) {
      if (improve_all) improve(a, stop);
      ants_[a].cost = static_cast<double>(problem_->cost(ants_[a].path));
    };
    if constexpr (HasLocalUpdate<Update>) {
      family_.construct_synchronous(rule_, update_, backend_, std::span<Solution>(ants_),
                                    std::span<Rng>(rngs_));
      backend_.for_each(ants, finish);
    } else {
      backend_.for_each(ants, [&](std::size_t a) {
        skipped_[a] = a > 0 && stop.expired() ? 1 : 0;
        if (skipped_[a] != 0) return;
        family_.construct(a, ants_[a].path, rngs_[a], rule_);
        finish(a);
      });
      for (std::size_t a = 1; a < ants; ++a)
        if (skipped_[a] != 0) ants_[a] = ants_[0];
    }
    check_costs();
    if (kHasLocalSearch && !improve_all) {
      rank();
      backend_.for_each(settings_.local_search_ants, [&](std::size_t r) {
        const std::size_t a = ranking_[r];
        improve(a, stop);
        ants_[a].cost = static_cast<double>(problem_->cost(ants_[a].path));
      });
      check_costs();
    }
    rank();

    const Solution& iteration_best = ants_[ranking_.front()];
    IterationReport report;
    report.iteration = iteration_;
    report.iteration_best = iteration_best.cost;
    report.improved = iteration_best.cost < best_.cost;
    if (report.improved) best_ = iteration_best;
    report.global_best = best_.cost;
    report.global_best_path = best_.path;
    // An iteration in which the stop token expired ends the run (run() stops after it), so its
    // trail update -- every ant's deposit on every edge of its tour, seconds on a million cities
    // -- would never be used.
    if (!stop.expired())
      update_.apply(family_.trail(), IterationView{ants_, ranking_, iteration_best, best_,
                                                   iteration_, ChunkedFor(backend_)});
    return report;
  }

  /// Runs from fresh trails until a termination criterion holds. Time budgets count from this
  /// call: building the colony (the heuristic values, the trails' initial values) comes before.
  RunResult run(const Termination& termination, const Observer& observer = {}) {
    validate(termination);
    // The trails were initialised when the colony was built (a nearest-neighbour tour of a
    // million cities takes about a second); a colony that has run before starts again from fresh
    // ones. The budget counts from here, after that preprocessing.
    if (iteration_ != 0) reset();
    using Clock = StopToken::Clock;
    const auto start = Clock::now();
    const double cpu_start = StopToken::cpu_seconds();
    const StopToken stop = budget_token(termination, start, cpu_start);
    RunResult result;
    for (;;) {
      IterationReport report = step(stop);
      report.elapsed_s = std::chrono::duration<double>(Clock::now() - start).count();
      if (report.improved) {
        result.time_to_best_s = report.elapsed_s;
        result.best_iteration = iteration_;
      }
      if (observer) observer(report);
      result.elapsed_s = report.elapsed_s;
      if (best_.cost <= termination.target_cost) {
        result.reason = StopReason::target;
      } else if (termination.max_iterations > 0 && iteration_ >= termination.max_iterations) {
        result.reason = StopReason::iterations;
      } else if (termination.time_limit_s > 0.0 && report.elapsed_s >= termination.time_limit_s) {
        result.reason = StopReason::time;
      } else if (termination.cpu_time_limit_s > 0.0 &&
                 StopToken::cpu_seconds() - cpu_start >= termination.cpu_time_limit_s) {
        result.reason = StopReason::cpu_time;
      } else if (termination.stagnation_iterations > 0 &&
                 iteration_ - result.best_iteration >= termination.stagnation_iterations) {
        result.reason = StopReason::stagnation;
      } else if (termination.stop.stop_requested()) {
        result.reason = StopReason::interrupted;
      } else {
        continue;
      }
      break;
    }
    result.best = best_;
    result.iterations = iteration_;
    result.settings = run_settings();
    return result;
  }

  /// What this colony runs with (the variant and rho are left to solve()).
  RunSettings run_settings() const {
    RunSettings ran;
    ran.colony = settings_;
    ran.local_search = kHasLocalSearch;
    ran.backend = backend_.kind();
    ran.threads = backend_.threads();
    return ran;
  }

  /// Island model (Manfrin et al. 2006): an immigrant, another colony's best-so-far, replaces
  /// this colony's best-so-far when it is strictly better. The pheromone updates read it from the
  /// next iteration on (IterationView::global_best: MMAS's trail limits, the best-so-far deposits
  /// of EAS, RAS, ACS and the hybrid) and so do focused ants choosing their source; an update that
  /// keeps a best of its own (MMAS's restart-best) adopts it too. Returns whether it was taken.
  bool receive(const Solution& immigrant) {
    if (!(immigrant.cost < best_.cost)) return false;
    best_ = immigrant;
    if constexpr (requires { update_.adopt(best_); }) update_.adopt(best_);
    return true;
  }

  const Problem& problem() const { return *problem_; }
  const Solution& best() const { return best_; }
  std::span<const Solution> ants() const { return ants_; }
  std::span<const std::uint32_t> ranking() const { return ranking_; }
  const Trail& trail() const { return family_.trail(); }
  const Update& update() const { return update_; }
  std::uint64_t iteration() const { return iteration_; }
  const ColonySettings& settings() const { return settings_; }

 private:
  void improve(std::size_t a, const StopToken& stop) {
    if constexpr (kHasLocalSearch && kCanFocus && kLocalSearchFromCities) {
      if (family_.focused()) {  // the source is a local optimum: start from the changed cities
        local_search_.improve(*problem_, ants_[a].path, workspaces_[a], rngs_[a], stop,
                              family_.new_edges(a));
        return;
      }
    }
    if constexpr (kHasLocalSearch)
      local_search_.improve(*problem_, ants_[a].path, workspaces_[a], rngs_[a], stop);
  }

  /// Throws std::invalid_argument unless every ant's cost is >= 0 (+infinity allowed): the
  /// ranking needs ordered costs and the deposits (eq. 2, 12) need costs >= 0; a problem that
  /// maximises a value v minimises, e.g., bound - v or 1 / (1 + v). Checked after the ants ran,
  /// not inside the parallel loop, where an exception could not leave an OpenMP team.
  void check_costs() const {
    for (const Solution& ant : ants_) {
      if (ant.cost >= 0.0) continue;
      std::ostringstream what;
      what << "aco: a solution's cost is " << ant.cost
           << "; a problem's costs must be numbers >= 0 (to maximise a value v, minimise e.g. "
              "bound - v or 1 / (1 + v))";
      throw std::invalid_argument(what.str());
    }
  }

  /// Focused construction from the second iteration on: the source is the best-so-far tour with
  /// probability focused.global_best_source, else the previous iteration's best (drawn from the
  /// stream after the last ant's, so it does not depend on threads).
  void choose_source() {
    if (!settings_.focused.enabled() || iteration_ < 2) return;
    Rng pick = ant_stream(settings_.seed, iteration_, settings_.ants);
    const bool global = pick.uniform() < settings_.focused.global_best_source;
    family_.set_source(global ? best_.path : ants_[ranking_.front()].path,
                       settings_.focused.min_new_edges);
  }

  /// Ant indices by increasing cost; ties keep ant order. (std::sort on (cost, index) is the
  /// stable order without stable_sort's buffer allocation on every iteration.)
  void rank() {
    std::iota(ranking_.begin(), ranking_.end(), 0U);
    std::sort(ranking_.begin(), ranking_.end(), [&](std::uint32_t a, std::uint32_t b) {
      return ants_[a].cost < ants_[b].cost || (ants_[a].cost == ants_[b].cost && a < b);
    });
  }

  const Problem* problem_;
  ColonySettings settings_;
  Rule rule_;
  Update update_;
  LocalSearch local_search_;
  Exec backend_;
  Family family_;
  std::vector<Solution> ants_;
  std::vector<std::uint8_t> skipped_;  ///< per ant: not built this iteration (stop expired)
  std::vector<Rng> rngs_;
  std::vector<std::uint32_t> ranking_;
  std::vector<typename LocalSearch::Workspace> workspaces_;
  Solution best_;
  std::uint64_t iteration_ = 0;
};

}  // namespace antslam::aco
