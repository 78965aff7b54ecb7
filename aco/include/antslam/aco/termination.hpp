#pragma once
// When a run stops, and the token that lets long phases (local search) stop inside an
// iteration when a budget runs out.

#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <limits>
#include <stdexcept>
#include <stop_token>
#include <string_view>
#include <utility>

namespace antslam::aco {

/// Stop criteria; any that is set can end the run. At least one must be set.
struct Termination {
  std::uint64_t max_iterations = 0;  ///< iterations to run; 0 = no limit
  double time_limit_s = 0.0;         ///< wall-clock budget in seconds; 0 = none
  double cpu_time_limit_s = 0.0;     ///< process CPU-time budget in seconds (all threads); 0 = none
  double target_cost = -std::numeric_limits<double>::infinity();  ///< stop once best <= target
  std::uint64_t stagnation_iterations = 0;  ///< stop after this many iterations without a new
                                            ///< global best; 0 = never
  std::stop_token stop{};  ///< once stop is requested (a user's Ctrl-C), the run ends after the
                           ///< current iteration and local searches end early; not a bound itself

  bool bounded() const {
    return max_iterations > 0 || time_limit_s > 0.0 || cpu_time_limit_s > 0.0 ||
           target_cost > -std::numeric_limits<double>::infinity() || stagnation_iterations > 0;
  }
};

/// Throws std::invalid_argument "termination: ..." for a time or CPU-time limit that is not a
/// finite number >= 0, a target that is not a number, or a run without any bound.
inline void validate(const Termination& t) {
  const auto budget = [](double s) { return std::isfinite(s) && s >= 0.0; };
  if (!budget(t.time_limit_s))
    throw std::invalid_argument(
        "termination: the time limit must be a finite number of seconds >= 0 (0: none)");
  if (!budget(t.cpu_time_limit_s))
    throw std::invalid_argument(
        "termination: the CPU-time limit must be a finite number of seconds >= 0 (0: none)");
  if (std::isnan(t.target_cost)) throw std::invalid_argument("termination: the target is NaN");
  if (!t.bounded())
    throw std::invalid_argument(
        "termination: set iterations, a time budget, a target or stagnation");
}

enum class StopReason { iterations, time, cpu_time, target, stagnation, interrupted };

constexpr std::string_view to_string(StopReason r) {
  switch (r) {
    case StopReason::iterations:
      return "iterations";
    case StopReason::time:
      return "time";
    case StopReason::cpu_time:
      return "cpu-time";
    case StopReason::target:
      return "target";
    case StopReason::stagnation:
      return "stagnation";
    case StopReason::interrupted:
      return "interrupted";
  }
  return "?";
}

/// Cheap to copy; polled by long-running phases. Default-constructed: never expires.
class StopToken {
 public:
  using Clock = std::chrono::steady_clock;

  StopToken() = default;
  StopToken(Clock::time_point wall_deadline, double cpu_deadline_s, std::stop_token request = {})
      : wall_deadline_(wall_deadline),
        cpu_deadline_s_(cpu_deadline_s),
        request_(std::move(request)) {}

  bool expired() const {
    if (request_.stop_requested()) return true;
    if (wall_deadline_ != Clock::time_point::max() && Clock::now() >= wall_deadline_) return true;
    return cpu_deadline_s_ < std::numeric_limits<double>::infinity() &&
           cpu_seconds() >= cpu_deadline_s_;
  }

  /// CPU time used by the whole process so far, in seconds.
  static double cpu_seconds() {
    return static_cast<double>(std::clock()) / static_cast<double>(CLOCKS_PER_SEC);
  }

 private:
  Clock::time_point wall_deadline_ = Clock::time_point::max();
  double cpu_deadline_s_ = std::numeric_limits<double>::infinity();
  std::stop_token request_;  // a stop requested from outside
};

/// The token that ends long phases once termination's clocks run out: the wall-clock budget
/// counted from `start`, the CPU-time budget from `cpu_start` (StopToken::cpu_seconds()).
inline StopToken budget_token(const Termination& termination, StopToken::Clock::time_point start,
                              double cpu_start) {
  using Clock = StopToken::Clock;
  return StopToken(termination.time_limit_s > 0.0
                       ? start + std::chrono::duration_cast<Clock::duration>(
                                     std::chrono::duration<double>(termination.time_limit_s))
                       : Clock::time_point::max(),
                   termination.cpu_time_limit_s > 0.0 ? cpu_start + termination.cpu_time_limit_s
                                                      : std::numeric_limits<double>::infinity(),
                   termination.stop);
}

}  // namespace antslam::aco
