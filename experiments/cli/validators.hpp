#pragma once
// CLI11 validators shared by every subcommand: they turn a nonsense option value into one clear
// line naming the option and the value.

#include <CLI/CLI.hpp>

namespace antslam::cli {

/// A finite number in [lo, hi].
CLI::Validator finite_in(double lo, double hi);
/// Decimal digits only (unsigned options would otherwise wrap "-1").
CLI::Validator non_negative_integer();

}  // namespace antslam::cli
