#pragma once
// The fragment-set file (JSON, versioned; docs/fragment-set-format.md): what the frontend
// writes and every optimizer reads. Loading validates everything (sizes, indices, finite
// numbers, symmetric positive definite covariances, format and version) and fails with one
// line naming the file, the field and the problem:
//   set.json: fragments[3].alignment.covariance: covariance is not positive definite

#include <filesystem>
#include <iosfwd>
#include <string>

#include "antslam/slamgraph/fragment_set.hpp"

namespace antslam::slam {

inline constexpr const char* kFragmentSetFormat = "antslam-fragment-set";
inline constexpr int kFragmentSetVersion = 1;

/// Bytes a set of this size takes in memory and while it is written (the JSON document of the
/// writer dominates), for refusing sizes that cannot fit before building the set.
double fragment_set_bytes(std::size_t fragments, std::size_t samples_per_fragment,
                          std::size_t trajectory_poses_per_fragment);

/// Writes the set (validated first) with round-trip precision.
void write_fragment_set(std::ostream& out, const FragmentSet& set);
/// Throws std::runtime_error "source: field: problem".
FragmentSet read_fragment_set(std::istream& in, const std::string& source);
FragmentSet read_fragment_set_file(const std::filesystem::path& path);

}  // namespace antslam::slam
