#pragma once
// Known optimal tour lengths: an optima.csv beside the instances, one row per instance
// "instance,n,edge_weight_type,optimal_length" (header row first), as in data/tsplib/.

#include <filesystem>
#include <optional>

namespace antslam::tsp {

/// The optimum listed for `instance_path` (matched by file stem) in the optima.csv of its
/// directory; nullopt when there is no such file or row. Throws std::runtime_error naming the
/// line on a malformed file.
std::optional<double> known_optimum(const std::filesystem::path& instance_path);

}  // namespace antslam::tsp
