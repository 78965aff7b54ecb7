#pragma once
// Many independent trials of one method (the paper averages 100): trial t runs with seed
// trial_seed(seed, t) and a serial colony; trials are spread over threads, and the results do
// not depend on how many.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "antslam/slamgraph/optimize.hpp"

namespace antslam::slam {

/// The seed of trial t of a study seeded with `seed`.
std::uint64_t trial_seed(std::uint64_t seed, std::size_t trial);

/// Called after each trial, serialised, with the number of trials finished so far.
using TrialsObserver = std::function<void(std::size_t finished)>;

/// How many trials, and how they are spread over threads.
struct TrialSettings {
  std::size_t trials = 1;   ///< independent trials (count)
  std::size_t threads = 0;  ///< threads the trials run on (0 = all cores)
  aco::BackendKind backend = aco::BackendKind::automatic;  ///< runs the trials in parallel
  /// The trials to run (indices < trials, results in this order), each exactly as in the whole
  /// study, so that processes can share a study's trials; all trials when empty.
  std::optional<std::vector<std::size_t>> only = std::nullopt;
};

/// One trial: the method of `settings` (seed, threads and backend set for the trial), with the
/// convergence observer (empty for trials that run beside others).
using TrialRunner =
    std::function<OptimizeResult(const OptimizeSettings& settings, const OptimizeObserver&)>;

/// Runs trials.trials trials of `run` as run_trials below does for a fragment set. Once
/// settings.stop is requested, several trials end with the longest run of trials (in the order
/// asked) that had finished before it: a trial it cut short, and every trial after one, is left
/// out, so that result k is still trial k. A single trial returns what it found when stopped.
std::vector<OptimizeResult> run_trials(const TrialRunner& run, const OptimizeSettings& settings,
                                       const TrialSettings& trials,
                                       const TrialsObserver& observer = {},
                                       const OptimizeObserver& convergence = {});

/// Runs trials.trials trials of settings.method (settings.seed seeds the study; settings.threads
/// and settings.backend are ignored). Several trials are spread over trials.threads threads by
/// trials.backend, each trial serial; a single trial runs its ants on them instead, and
/// `convergence` sees its every improvement. The results do not depend on the threads.
std::vector<OptimizeResult> run_trials(const FragmentSet& set, const OptimizeSettings& settings,
                                       const TrialSettings& trials,
                                       const TrialsObserver& observer = {},
                                       const OptimizeObserver& convergence = {});

/// Bytes one trial's result holds for this many poses (fragments or graph vertices: frames,
/// alignments, choice and a convergence record of typical length), so that a caller can refuse
/// a trial count that cannot fit in memory before running it.
double trial_result_bytes(std::size_t poses);

/// The trial with the lowest eq. (10) weight (the first on ties); throws on an empty span.
std::size_t best_trial(std::span<const OptimizeResult> trials);

struct Statistics {
  double mean = 0.0;  ///< arithmetic mean
  double std = 0.0;   ///< sample standard deviation (n - 1); 0 for one value
  double min = 0.0;   ///< smallest value
  double max = 0.0;   ///< largest value
};

/// Throws std::invalid_argument for an empty span.
Statistics statistics(std::span<const double> values);

}  // namespace antslam::slam
