#pragma once
// The result files of an optimisation study (docs/fragment-set-format.md): the result (JSON,
// versioned: statistics over the trials and the best trial's map: weight, chi2, chosen samples,
// alignments, world poses of every fragment), a row per trial and per improvement (CSV). They
// hold no wall-clock values, so a seed gives byte-identical files on any thread count, backend
// or number of processes; the times go to a separate file.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <span>
#include <string>

#include "antslam/slamgraph/optimize.hpp"
#include "antslam/slamgraph/trials.hpp"

namespace antslam::slam {

inline constexpr const char* kResultFormat = "antslam-optimize-result";
inline constexpr int kResultVersion = 3;  ///< 3 added the settings; 1 also held the times
                                          ///< (every version is still read)
inline constexpr const char* kTimesFormat = "antslam-optimize-times";

/// The best trial's frames against a reference (computed by the caller, e.g. with antslam::eval:
/// rigid SE(2) alignment, then the absolute trajectory error).
struct TrajectoryError {
  double rmse_m = 0.0;    ///< translation RMSE, metres
  double max_m = 0.0;     ///< largest translation error, metres
  double rmse_deg = 0.0;  ///< heading RMSE, degrees
  std::size_t poses = 0;  ///< poses compared
};

/// A study stopped early (Ctrl-C): its result holds the trials finished before the stop.
struct StudyInterruption {
  std::string signal;                ///< "SIGINT", "SIGTERM" or "SIGHUP"
  std::size_t trials_requested = 0;  ///< the study asked for this many (count)
};

struct StudyResult {
  std::string fragment_set;                      ///< what was optimised (file or name)
  Method method = Method::hybrid;                ///< how
  std::uint64_t seed = 1;                        ///< study seed (trial t: trial_seed(seed, t))
  std::size_t trials = 0;                        ///< number of trials
  Statistics weight;                             ///< eq. (10) over the trials
  Statistics chi2;                               ///< least-squares cost over the trials
  Statistics elapsed_s;                          ///< wall-clock seconds per trial (not in the file)
  std::size_t best_trial = 0;                    ///< trial with the lowest weight (first on ties)
  OptimizeResult best;                           ///< that trial's result (convergence not stored)
  std::optional<TrajectoryError> error;          ///< best trial's frames vs the reference, if known
  std::optional<StudyInterruption> interrupted;  ///< set when the study was stopped early
  /// The settings every trial ran with, those that decide its result (not threads, backend,
  /// the stop or the islands' exchange); from summarize, or read from a version 3 file.
  std::optional<OptimizeSettings> settings;
};

/// Statistics of the trials and the best one (no trajectory error: the caller adds it).
StudyResult summarize(const std::string& fragment_set, const OptimizeSettings& settings,
                      std::span<const OptimizeResult> trials);

void write_result(std::ostream& out, const StudyResult& result);
/// Throws std::runtime_error "source: field: problem".
StudyResult read_result(std::istream& in, const std::string& source);
StudyResult read_result_file(const std::filesystem::path& path);

/// One row per trial: trial,seed,weight,chi2,iterations,evaluations
/// (seed: trial_seed(study_seed, trial)).
void write_trials_csv(std::ostream& out, std::span<const OptimizeResult> trials,
                      std::uint64_t study_seed);
/// One row per improvement of each trial's best weight: trial,iteration,evaluations,best_weight
void write_convergence_csv(std::ostream& out, std::span<const OptimizeResult> trials);
/// The wall-clock times (JSON): statistics of the seconds per trial, and per trial its seconds,
/// the seconds until its best, and [iteration, seconds] of every improvement (the rows of the
/// convergence CSV, in order).
void write_times_json(std::ostream& out, std::span<const OptimizeResult> trials);

}  // namespace antslam::slam
