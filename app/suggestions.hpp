#pragma once
// "Did you mean": the closest option or command name to a mistyped one on the command line.

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace antslam::cli {

/// Edit distance (insertions, deletions, substitutions, transpositions of neighbours).
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidate closest to `typed` if it is close enough to be a typo (an edit distance of at
/// most a third of its length, and at least 1 and at most 3), else nothing.
std::optional<std::string> closest(std::string_view typed, const std::vector<std::string>& names);

/// After `app` failed to parse: " (unknown --varient: did you mean --variant?)" for the first
/// argument it left over that is close to an option of the command being parsed (or to a
/// command name), else "".
std::string did_you_mean(const CLI::App& app);

}  // namespace antslam::cli
