#pragma once
// False loop closures for robustness benchmarks, following the protocol of Suenderhauf & Protzel
// (2012) and their Vertigo generator: each false closure joins vertices v1 < v2 drawn uniformly
// (random) or with v2 at most `local_window` vertices after v1 (local), never consecutive ones,
// with a measurement drawn from N(0, 0.3 m) in x and y and N(0, 10 deg) in theta, and the
// information matrix 42.7 I. The group kinds add groups of `group_size` closures (v1 + j, v2 + j),
// j = 0..K-1, that share one measurement: mutually consistent, the hard case for consistency
// checks. They are appended after the graph's own edges.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "antslam/slamgraph/chain.hpp"
#include "antslam/slamgraph/g2o.hpp"

namespace antslam::slam {

enum class OutlierKind { random, local, random_group, local_group };

struct OutlierKindInfo {
  OutlierKind value;
  std::string_view name;     ///< the name options and files use
  std::string_view summary;  ///< one line for help texts
};

inline constexpr std::array<OutlierKindInfo, 4> kOutlierKinds{{
    {OutlierKind::random, "random", "between uniformly drawn vertices"},
    {OutlierKind::local, "local", "to a vertex at most local_window vertices later"},
    {OutlierKind::random_group, "random-group",
     "groups of consecutive random ones, one measurement"},
    {OutlierKind::local_group, "local-group", "groups of consecutive local ones, one measurement"},
}};

std::string_view to_string(OutlierKind kind);
std::optional<OutlierKind> parse_outlier_kind(std::string_view name);

struct OutlierSettings {
  std::size_t count = 100;                 ///< false closures to add (count)
  OutlierKind kind = OutlierKind::random;  ///< how their vertices are drawn
  std::size_t group_size = 10;             ///< closures per group (count; group kinds only; the
                                           ///< last group holds the remainder)
  std::size_t local_window = 20;           ///< local kinds: v2 - v1 at most this (vertices)
  double sigma_xy = 0.3;                   ///< std of the measured x and y, metres
  double sigma_theta = 10.0 * std::numbers::pi / 180.0;  ///< std of the measured angle, radians
  double information = 42.7;  ///< diagonal of the information matrix (1/m^2, 1/rad^2)
  std::uint64_t seed = 1;     ///< seeds every draw
};

struct SpoiledGraph {
  PoseGraph graph;                                            ///< the graph plus the false closures
  std::vector<std::pair<std::size_t, std::size_t>> outliers;  ///< (v1, v2) of each, in order
};

/// Throws std::invalid_argument for a graph too small for the settings (fewer than
/// group_size + 3 vertices) or invalid settings.
SpoiledGraph add_outliers(const PoseGraph& graph, const OutlierSettings& settings);

/// `v1 v2` per line.
void write_outlier_pairs(std::ostream& out,
                         const std::vector<std::pair<std::size_t, std::size_t>>& outliers);

/// Which loop closures (in split.closures order) a file of `i j` lines names as false: each line
/// marks the last closure between i and j (either direction) that no later line marked, so
/// appended false closures are found even where a true closure joins the same vertices. Throws
/// std::runtime_error "path:line: problem" for malformed lines and pairs that name no closure.
std::vector<bool> read_outlier_flags(const std::filesystem::path& path, const PoseGraph& graph,
                                     const ChainSplit& split);

/// OUT.g2o -> OUT.outliers.txt: where the outlier list of a graph file lives.
std::filesystem::path outliers_path_of(const std::filesystem::path& graph_path);

}  // namespace antslam::slam
