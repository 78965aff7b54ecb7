#pragma once
// CLI11 validators shared by every subcommand: they turn a nonsense option value into one clear
// line naming the option and the value, at parse time, before any work. Every numeric option
// has one (tests/app/test_cli_options.cpp feeds each "-1", "nan", "1e400" and 2^64).

#include <CLI/CLI.hpp>

#include <cstdint>
#include <limits>

namespace antslam::cli {

// Upper bounds shared by several commands' options.
inline constexpr std::uint64_t kMaxThreads = 1024;       ///< --threads (count)
inline constexpr std::uint64_t kMaxTrials = 1'000'000;   ///< --trials (count)
inline constexpr std::uint64_t kMaxSamples = 1'000'000;  ///< -m/--samples per alignment (count)

/// A finite number in [lo, hi].
CLI::Validator finite_in(double lo, double hi);

/// A finite number >= 0 (a tolerance, a time), without an upper bound.
CLI::Validator finite_at_least_zero();
/// A finite number > 0 (a distance, a step), without an upper bound.
CLI::Validator finite_positive();

/// An integer in [lo, hi] written in decimal digits only: no sign (unsigned options would wrap
/// "-1"), no value beyond 2^64 - 1 (CLI11 would saturate it), no octal or hex (the text is
/// rewritten in plain decimal, which CLI11 then converts).
CLI::Validator count_in(std::uint64_t lo, std::uint64_t hi);

/// count_in(0, 2^64 - 1): seeds and other unbounded counts.
CLI::Validator non_negative_integer();

}  // namespace antslam::cli
