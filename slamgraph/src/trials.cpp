#include "antslam/slamgraph/trials.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

#include "antslam/aco/backend_factory.hpp"
#include "antslam/aco/random.hpp"

namespace antslam::slam {

std::uint64_t trial_seed(std::uint64_t seed, std::size_t trial) {
  return aco::mix_seed(seed, trial, 0x7472);
}

namespace {

/// The trials to run: trials.only, checked, or every index.
std::vector<std::size_t> trials_to_run(const TrialSettings& trials) {
  if (!trials.only) {
    std::vector<std::size_t> all(trials.trials);
    for (std::size_t t = 0; t < all.size(); ++t) all[t] = t;
    return all;
  }
  for (const std::size_t t : *trials.only)
    if (t >= trials.trials)
      throw std::invalid_argument("trial " + std::to_string(t) + " of a study of " +
                                  std::to_string(trials.trials) + " trials");
  return *trials.only;
}

}  // namespace

std::vector<OptimizeResult> run_trials(const TrialRunner& run, const OptimizeSettings& settings,
                                       const TrialSettings& trials, const TrialsObserver& observer,
                                       const OptimizeObserver& convergence) {
  if (trials.trials == 0) throw std::invalid_argument("trials must be >= 1");
  const std::vector<std::size_t> indices = trials_to_run(trials);
  if (trials.trials == 1) {  // the one trial runs its ants on the threads
    std::vector<OptimizeResult> results;
    if (indices.empty()) return results;
    OptimizeSettings s = settings;
    s.seed = trial_seed(settings.seed, 0);
    s.threads = trials.threads;
    s.backend = trials.backend;
    results.push_back(run(s, convergence));
    if (observer) observer(1);
    return results;
  }
  std::vector<OptimizeResult> results(indices.size());
  std::vector<std::uint8_t> complete(indices.size(), 0);  // finished before any stop
  std::mutex mutex;
  std::size_t finished = 0;
  aco::with_backend(trials.backend, trials.threads, [&](auto backend) {
    backend.for_each(indices.size(), [&](std::size_t k) {
      if (settings.stop.stop_requested()) return;
      OptimizeSettings s = settings;
      s.seed = trial_seed(settings.seed, indices[k]);
      s.threads = 1;
      s.backend = aco::BackendKind::serial;
      results[k] = run(s, {});
      if (settings.stop.stop_requested()) return;  // perhaps cut short
      complete[k] = 1;
      const std::lock_guard lock(mutex);
      ++finished;
      if (observer) observer(finished);
    });
  });
  const auto first_missing = std::find(complete.begin(), complete.end(), 0);
  results.resize(static_cast<std::size_t>(first_missing - complete.begin()));
  return results;
}

std::vector<OptimizeResult> run_trials(const FragmentSet& set, const OptimizeSettings& settings,
                                       const TrialSettings& trials, const TrialsObserver& observer,
                                       const OptimizeObserver& convergence) {
  validate(set);
  return run_trials(
      [&set](const OptimizeSettings& s, const OptimizeObserver& o) { return optimize(set, s, o); },
      settings, trials, observer, convergence);
}

double trial_result_bytes(std::size_t poses) {
  constexpr double kConvergencePoints = 64;  // improvements recorded per trial, typically
  const auto n = static_cast<double>(poses);
  return static_cast<double>(sizeof(OptimizeResult)) +
         n * (2.0 * sizeof(Pose2) + sizeof(std::uint32_t)) +
         kConvergencePoints * sizeof(ConvergencePoint);
}

std::size_t best_trial(std::span<const OptimizeResult> trials) {
  if (trials.empty()) throw std::invalid_argument("best_trial: no trials");
  std::size_t best = 0;
  for (std::size_t t = 1; t < trials.size(); ++t)
    if (trials[t].scores.weight < trials[best].scores.weight) best = t;
  return best;
}

Statistics statistics(std::span<const double> values) {
  if (values.empty()) throw std::invalid_argument("statistics of no values");
  Statistics s;
  s.min = *std::min_element(values.begin(), values.end());
  s.max = *std::max_element(values.begin(), values.end());
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / static_cast<double>(values.size());
  if (values.size() > 1) {
    double sq = 0.0;
    for (double v : values) sq += (v - s.mean) * (v - s.mean);
    s.std = std::sqrt(sq / static_cast<double>(values.size() - 1));
  }
  return s;
}

}  // namespace antslam::slam
