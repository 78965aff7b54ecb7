#pragma once
// The island model of multi-colony ACO (Middendorf, Reischle & Schmeck 2002; Manfrin, Birattari,
// Stuetzle & Dorigo 2006): K colonies of one variant run in lockstep, iteration by iteration;
// every E iterations each colony offers its best-so-far and receives the best offer of its
// neighbours in a topology (ring: the colony before it; full: every other colony), which
// replaces its own best-so-far when it is better (Colony::receive).
//
// The colonies may live in one process or be spread over several (MPI ranks): this process runs
// colonies first .. first + local - 1, and the Exchange the caller supplies gathers every
// colony's offer in colony order at every iteration boundary (within one process the identity;
// over MPI an all-gather). Every decision after the gather -- who receives what, whether the run
// stops and why -- reads only the gathered offers, so every process takes it alike. Colony c's
// seed depends on c only (colony_seed), never on where it runs: a run bounded by iterations is
// bit-identical for a given (seed, K, topology, E), however its colonies are spread over
// processes and whatever each colony's backend and thread count.

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "antslam/aco/colony.hpp"
#include "antslam/aco/random.hpp"
#include "antslam/aco/solution.hpp"
#include "antslam/aco/termination.hpp"
#include "antslam/aco/variants.hpp"

namespace antslam::aco {

enum class Topology { ring, full };

constexpr std::string_view to_string(Topology t) { return t == Topology::ring ? "ring" : "full"; }

/// The topology a name (to_string's) stands for; none for another name.
constexpr std::optional<Topology> parse_topology(std::string_view name) {
  for (const Topology t : {Topology::ring, Topology::full})
    if (to_string(t) == name) return t;
  return std::nullopt;
}

struct IslandSettings {
  std::size_t colonies = 1;           ///< K
  std::uint64_t exchange_every = 25;  ///< E: iterations between exchanges
  Topology topology = Topology::ring;
  std::size_t first = 0;  ///< the first colony this process runs
  std::size_t local = 0;  ///< how many colonies this process runs (0: all from `first` on)
};

/// Colony c's seed: the run's own seed for colony 0 (one island is the plain run), the seed
/// mixed with c for the others.
constexpr std::uint64_t colony_seed(std::uint64_t seed, std::size_t colony) {
  constexpr std::uint64_t kIslandStream = 0x151A2D5ULL;
  return colony == 0 ? seed : mix_seed(seed, colony, kIslandStream);
}

/// What a colony tells the others at an iteration boundary.
struct Offer {
  double best = std::numeric_limits<double>::infinity();            ///< best-so-far cost
  double iteration_best = std::numeric_limits<double>::infinity();  ///< this iteration's best
  std::vector<std::uint32_t> path;  ///< best-so-far path when paths travel, else empty
  std::uint8_t stop = 0;            ///< 0: go on; else 1 + the StopReason its clocks call for
};

/// Gathers every colony's offer in colony order from this process's offers (of colonies
/// first .. first + local - 1). Every process calls it at every iteration boundary (a collective
/// over processes). `failure` is set when this process's colonies failed: the exchange must then
/// throw on every process at this boundary, so that none waits for the failed one.
using Exchange =
    std::function<std::vector<Offer>(std::vector<Offer> local, const std::exception_ptr& failure)>;

/// The exchange of a run in one process: every colony is local.
inline std::vector<Offer> in_process_exchange(std::vector<Offer> local,
                                              const std::exception_ptr& failure) {
  if (failure) std::rethrow_exception(failure);
  return local;
}

/// What the island observer hears after every iteration boundary.
struct IslandReport {
  IterationReport run;     ///< over all colonies (global_best_path empty: paths travel rarely)
  bool exchanged = false;  ///< colonies received their neighbours' offers
  std::span<const double> offered;  ///< every colony's best-so-far before it, colony order
  std::span<const double> local;    ///< this process's colonies' best-so-far after it
  std::size_t first = 0;            ///< the colony local[0] belongs to
};
using IslandObserver = std::function<void(const IslandReport&)>;

struct IslandResult {
  RunResult run;  ///< best over all colonies (ties: the lowest colony), iterations, times, stop
                  ///< reason; settings of colony 0 with the run's seed
  std::size_t best_colony = 0;
  std::vector<double> colony_best;  ///< every colony's best cost at the end, colony order
  std::uint64_t exchanges = 0;      ///< boundaries at which colonies received offers
  std::uint64_t immigrants = 0;     ///< offers this process's colonies took (better than theirs)
  double exchange_s = 0.0;  ///< wall-clock seconds this process spent in the exchange, waiting
                            ///< for the other processes included
};

/// The colony whose offer colony c receives: its ring predecessor, or (full) the best other
/// colony, ties to the lowest index.
inline std::size_t immigrant_source(std::size_t c, std::span<const Offer> offers,
                                    Topology topology) {
  const std::size_t k = offers.size();
  if (topology == Topology::ring) return (c + k - 1) % k;
  std::size_t source = c == 0 ? 1 : 0;
  for (std::size_t j = source + 1; j < k; ++j)
    if (j != c && offers[j].best < offers[source].best) source = j;
  return source;
}

namespace detail {

inline void check(const IslandSettings& s, const Termination& termination) {
  if (s.colonies == 0) throw std::invalid_argument("islands: need at least one colony");
  if (s.exchange_every == 0) throw std::invalid_argument("islands: exchange_every must be >= 1");
  if (s.first >= s.colonies || s.first + s.local > s.colonies)
    throw std::invalid_argument("islands: this process's colonies lie outside 0 .. K-1");
  validate(termination);
}

/// 1 + the reason this process's clocks (or a stop request) end the run, else 0.
inline std::uint8_t clock_stop(const Termination& t, double elapsed_s, double cpu_start) {
  const auto code = [](StopReason r) { return static_cast<std::uint8_t>(1 + static_cast<int>(r)); };
  if (t.time_limit_s > 0.0 && elapsed_s >= t.time_limit_s) return code(StopReason::time);
  if (t.cpu_time_limit_s > 0.0 && StopToken::cpu_seconds() - cpu_start >= t.cpu_time_limit_s)
    return code(StopReason::cpu_time);
  if (t.stop.stop_requested()) return code(StopReason::interrupted);
  return 0;
}

/// Why the run stops at this boundary (the same on every process: it reads the offers only).
inline std::optional<StopReason> agreed_stop(const Termination& t, std::span<const Offer> offers,
                                             double best, std::uint64_t iteration,
                                             std::uint64_t best_iteration) {
  if (best <= t.target_cost) return StopReason::target;
  if (t.max_iterations > 0 && iteration >= t.max_iterations) return StopReason::iterations;
  std::uint8_t clock = 0;
  for (const Offer& o : offers)
    if (o.stop != 0 && (clock == 0 || o.stop < clock)) clock = o.stop;
  if (clock != 0) return static_cast<StopReason>(clock - 1);
  if (t.stagnation_iterations > 0 && iteration - best_iteration >= t.stagnation_iterations)
    return StopReason::stagnation;
  return std::nullopt;
}

}  // namespace detail

/// Runs the island model: make_colony(c) builds colony c (a std::unique_ptr to a Colony seeded
/// with colony_seed(seed, c)); this process steps colonies first .. first + local - 1 from fresh
/// trails. Termination is decided for all colonies at each boundary: the iteration budget,
/// a target reached by any colony, stagnation of the best over all colonies, or any process's
/// clocks (wall-clock or CPU budget, counted by each process once its colonies are built; a stop
/// request).
template <class MakeColony>
IslandResult run_islands(MakeColony&& make_colony, IslandSettings s, const Termination& termination,
                         const Exchange& exchange = in_process_exchange,
                         const IslandObserver& observer = {}) {
  if (s.local == 0) s.local = s.colonies - std::min(s.first, s.colonies);
  detail::check(s, termination);
  using Clock = StopToken::Clock;
  const std::size_t k = s.colonies;

  std::vector<decltype(make_colony(std::size_t{0}))> colonies;
  std::exception_ptr failure;
  try {
    for (std::size_t i = 0; i < s.local; ++i) colonies.push_back(make_colony(s.first + i));
  } catch (...) {
    failure = std::current_exception();
  }
  // The budgets count from here, after the colonies were built (as Colony::run's).
  const auto start = Clock::now();
  const double cpu_start = StopToken::cpu_seconds();
  const StopToken stop = budget_token(termination, start, cpu_start);

  IslandResult result;
  const auto gather = [&](std::vector<Offer> mine) {
    const auto begin = Clock::now();
    std::vector<Offer> all = exchange(std::move(mine), failure);
    result.exchange_s += std::chrono::duration<double>(Clock::now() - begin).count();
    if (all.size() != k) throw std::logic_error("islands: the exchange lost colonies");
    return all;
  };
  std::vector<double> offered(k);
  std::vector<double> local_best(s.local);
  double best = std::numeric_limits<double>::infinity();
  std::vector<Offer> all;
  bool paths = false;  // whether the offers of this boundary carry paths
  for (std::uint64_t iteration = 1;; ++iteration) {
    paths = k > 1 && iteration % s.exchange_every == 0;
    std::vector<Offer> mine(s.local);
    if (!failure) {
      try {
        for (std::size_t i = 0; i < s.local; ++i) {
          const IterationReport r = colonies[i]->step(stop);
          mine[i].best = r.global_best;
          mine[i].iteration_best = r.iteration_best;
          if (paths) mine[i].path = colonies[i]->best().path;
        }
        const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        const std::uint8_t clock = detail::clock_stop(termination, elapsed, cpu_start);
        for (Offer& o : mine) o.stop = clock;
      } catch (...) {
        failure = std::current_exception();
      }
    }
    all = gather(std::move(mine));

    IslandReport report;
    report.run.iteration = iteration;
    report.run.elapsed_s = std::chrono::duration<double>(Clock::now() - start).count();
    report.run.iteration_best = std::numeric_limits<double>::infinity();
    double offered_best = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < k; ++c) {
      offered[c] = all[c].best;
      offered_best = std::min(offered_best, all[c].best);
      report.run.iteration_best = std::min(report.run.iteration_best, all[c].iteration_best);
    }
    report.run.improved = offered_best < best;
    if (report.run.improved) {
      best = offered_best;
      result.run.best_iteration = iteration;
      result.run.time_to_best_s = report.run.elapsed_s;
    }
    report.run.global_best = best;
    const std::optional<StopReason> reason =
        detail::agreed_stop(termination, all, best, iteration, result.run.best_iteration);
    report.exchanged = paths && !reason;
    if (report.exchanged) ++result.exchanges;
    try {  // a failure here reaches the other processes at the next gather
      if (report.exchanged)
        for (std::size_t i = 0; i < s.local; ++i) {
          const Offer& from = all[immigrant_source(s.first + i, all, s.topology)];
          if (colonies[i]->receive(Solution{from.path, from.best})) ++result.immigrants;
        }
      for (std::size_t i = 0; i < s.local; ++i) local_best[i] = colonies[i]->best().cost;
      report.offered = offered;
      report.local = local_best;
      report.first = s.first;
      if (observer) observer(report);
    } catch (...) {
      failure = std::current_exception();
    }
    result.run.elapsed_s = report.run.elapsed_s;
    if (!reason) continue;

    result.run.reason = *reason;
    result.run.iterations = iteration;
    break;
  }
  if (!paths) {  // the best path travels once more, to every process
    std::vector<Offer> mine(s.local);
    for (std::size_t i = 0; i < s.local; ++i)
      mine[i] = Offer{colonies[i]->best().cost, 0.0, colonies[i]->best().path, 0};
    all = gather(std::move(mine));
  }
  if (failure) std::rethrow_exception(failure);  // the last boundary's observer failed here
  for (std::size_t c = 0; c < k; ++c) {
    result.colony_best.push_back(all[c].best);
    if (all[c].best < all[result.best_colony].best) result.best_colony = c;
  }
  result.run.best = Solution{all[result.best_colony].path, all[result.best_colony].best};
  result.run.settings = colonies.front()->run_settings();
  return result;
}

/// The island model of p.variant on `problem`: make_backend() gives each colony its backend,
/// each colony a copy of local_search; the result records the settings that ran, with the run's
/// seed (p.seed; colony c ran with colony_seed(p.seed, c)).
template <class Problem, class LocalSearch, class MakeBackend>
IslandResult solve_islands(const Problem& problem, const Parameters& p,
                           const Termination& termination, MakeBackend&& make_backend,
                           const LocalSearch& local_search, const IslandSettings& islands,
                           const Exchange& exchange = in_process_exchange,
                           const IslandObserver& observer = {}) {
  constexpr bool kLs = !std::is_same_v<LocalSearch, NoLocalSearch>;
  const ColonySettings settings = colony_settings_for(problem, p, kLs);
  const double rho = resolved_rho(p, kLs);
  IslandResult result = with_variant_policies(p, rho, [&](auto rule, auto update) {
    using Exec = std::remove_cvref_t<decltype(make_backend())>;
    using C = Colony<Problem, decltype(rule), decltype(update), LocalSearch, Exec>;
    const auto make_colony = [&](std::size_t c) {
      ColonySettings mine = settings;
      mine.seed = colony_seed(p.seed, c);
      return std::make_unique<C>(problem, mine, rule, update, local_search, make_backend());
    };
    return run_islands(make_colony, islands, termination, exchange, observer);
  });
  result.run.settings.variant = p.variant;
  result.run.settings.rho = rho;
  result.run.settings.colony.seed = p.seed;
  return result;
}

}  // namespace antslam::aco
