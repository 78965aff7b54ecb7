#include "validators.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <string>

namespace antslam::cli {

CLI::Validator finite_in(double lo, double hi) {
  std::ostringstream description;
  description << "finite number in [" << lo << ", " << hi << "]";
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        double v = 0.0;
        try {
          std::size_t used = 0;
          v = std::stod(text, &used);
          if (used != text.size()) return "'" + text + "' is not a number";
        } catch (const std::exception&) {
          return "'" + text + "' is not a finite number";
        }
        if (!std::isfinite(v)) return "'" + text + "' is not a finite number";
        if (v < lo || v > hi)
          return "'" + text + "' is not in [" + CLI::detail::to_string(lo) + ", " +
                 CLI::detail::to_string(hi) + "]";
        return {};
      },
      description.str());
}

namespace {

/// Finite numbers > 0, or >= 0 with allow_zero (CLI11 alone would let "nan" through).
CLI::Validator finite_number(bool allow_zero) {
  return CLI::Validator(
      [allow_zero](std::string& text) -> std::string {
        double value = 0.0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        const bool valid = ec == std::errc() && ptr == end && std::isfinite(value) &&
                           (value > 0.0 || (allow_zero && value == 0.0));
        if (valid) return {};
        return "'" + text + "' is not a finite number " + (allow_zero ? ">= 0" : "> 0");
      },
      allow_zero ? "FINITE>=0" : "FINITE>0");
}

}  // namespace

CLI::Validator finite_at_least_zero() { return finite_number(true); }

CLI::Validator finite_positive() { return finite_number(false); }

CLI::Validator count_in(std::uint64_t lo, std::uint64_t hi) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        const bool digits =
            !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        if (!digits) return "'" + text + "' is not a whole number in " + range;
        std::uint64_t value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size() || value < lo || value > hi)
          return "'" + text + "' is not a whole number in " + range;
        text = std::to_string(value);
        return {};
      },
      "whole number in " + range);
}

CLI::Validator non_negative_integer() {
  return count_in(0, std::numeric_limits<std::uint64_t>::max());
}

}  // namespace antslam::cli
