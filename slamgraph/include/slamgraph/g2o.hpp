#pragma once
// 2D pose graphs in g2o format: `VERTEX_SE2 id x y theta` and
// `EDGE_SE2 i j dx dy dtheta I11 I12 I13 I22 I23 I33` (the measurement is the pose of j in i's
// frame; I is the upper triangle of the information matrix). Standard graphs become fragment
// sets, and results go back to g2o, so every optimizer runs on data/posegraphs.
//
// Import: vertex i is fragment i. The first edge between vertices i-1 and i (either direction;
// inverted if given as (i, i-1)) is fragment i's alignment N(mu_i, Omega^-1) with M samples
// drawn from it (eq. 7); its mean is also E_{i-1} (eq. 4). Every other edge is a loop closure
// from a = min(i, j) to b = max(i, j) with anchor = identity (the frame origin of F_b),
// the measurement inverted when i > j. Inverting a measurement z with covariance Sigma gives
// z^-1 with covariance J Sigma J^T, J = d(z^-1)/dz at the measurement (first order).

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

#include "slamgraph/fragment_set.hpp"

namespace antslam::slam {

struct PoseGraphEdge {
  std::size_t from = 0;         ///< vertex i
  std::size_t to = 0;           ///< vertex j
  Pose2 measurement;            ///< pose of j in i's frame
  Eigen::Matrix3d information;  ///< symmetric positive definite
};

struct PoseGraph {
  std::vector<Pose2> vertices;       ///< vertex id = index
  std::vector<PoseGraphEdge> edges;  ///< in file order
};

/// Throws std::runtime_error "source:line: problem" on unknown tags, wrong field counts,
/// non-numbers, non-finite values, information matrices that are not positive definite, vertex
/// ids that are not 0..n-1 exactly once, edges to unknown vertices or to themselves.
PoseGraph read_g2o(std::istream& in, const std::string& source);
PoseGraph read_g2o_file(const std::filesystem::path& path);
/// Writes vertices then edges with round-trip precision.
void write_g2o(std::ostream& out, const PoseGraph& graph);

struct G2oImportSettings {
  std::size_t samples = 20;  ///< M samples drawn per alignment (eq. 7)
  std::uint64_t seed = 1;    ///< seeds the samples
};

/// Returns a valid set (validate()). Throws std::invalid_argument naming `source` if some vertex
/// i >= 1 has no edge to i - 1, if an edge gives no Gaussian, or if the set is not valid.
FragmentSet fragment_set_from_g2o(const PoseGraph& graph, const G2oImportSettings& settings,
                                  const std::string& source);

/// The graph of a fragment set with the given world frames as vertices: alignments as edges
/// (i-1, i) with their means, closures as edges (a, b) with measurement H * anchor^-1.
PoseGraph pose_graph_of(const FragmentSet& set, std::span<const Pose2> frames);

/// Reference poses of a graph's vertices for evaluation: a .g2o file (its vertices), a TUM
/// trajectory (.tum) or lines of `x y theta` (e.g. manhattan3500.gt.dat). Throws
/// std::runtime_error "source:line: problem".
std::vector<Pose2> read_reference_poses(const std::filesystem::path& path);

/// The edge's measurement as a Gaussian over the pose of the other vertex in the frame of
/// vertex `from` (one of the edge's ends): inverted, to first order, when the edge is stored the
/// other way round.
Gaussian2 oriented(const PoseGraphEdge& edge, std::size_t from);

/// A fragment set from a file: fragment_set_from_g2o of a pose graph if the name ends in .g2o,
/// a fragment-set JSON (fragment_set_io.hpp) otherwise.
FragmentSet read_optimizer_input(const std::filesystem::path& path,
                                 const G2oImportSettings& settings);

/// Reference poses of the set's fragments: the set's own `reference` if `path` is empty, else
/// read_reference_poses(path). Throws std::runtime_error if a file's pose count is not the
/// set's fragment count.
std::vector<Pose2> reference_frames(const FragmentSet& set, const std::filesystem::path& path);

/// Covariance of z^-1 for z ~ N(measurement, covariance), to first order.
Eigen::Matrix3d inverse_covariance(const Pose2& measurement, const Eigen::Matrix3d& covariance);

}  // namespace antslam::slam
