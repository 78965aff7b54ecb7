#pragma once
// 2D pose graphs as they are found in the public benchmark sets, in two formats:
//   g2o   VERTEX_SE2 id x y theta
//         EDGE_SE2 i j dx dy dtheta I11 I12 I13 I22 I23 I33   (information: upper triangle by rows)
//         FIX id [id ...]                                    (vertices held fixed)
//   TORO  VERTEX2 id x y theta
//         EDGE2 i j dx dy dtheta Ixx Ixy Iyy Itt Ixt Iyt     (TORO's order of the information)
// In both the measurement is the pose of j in i's frame. Either tag set is read from any file;
// the writer picks the format by the file name (.graph: TORO).
//
// Files without vertex lines (SE-Sync's benchmark graphs have only EDGE_SE2): the vertices are
// the ids the edges use, 0..n-1, and their poses compose the edges along a spanning tree from
// vertex 0, odometry edges (consecutive ids) first (graph_structure.hpp), so that a single
// session starts from its odometry chain. Files with vertices: their estimates are the initial
// guess of every continuous optimizer, and the fixed vertices (FIX lines; vertex 0 without any)
// stay where the file puts them.
//
// Import as a fragment set (the ants' problem): vertex i is fragment i. The first edge between
// vertices i-1 and i (either direction; inverted if given as (i, i-1)) is fragment i's alignment
// N(mu_i, Omega^-1) with M samples drawn from it (eq. 7); its mean is also E_{i-1} (eq. 4). Every
// other edge is a loop closure from a = min(i, j) to b = max(i, j) with anchor = identity (the
// frame origin of F_b), the measurement inverted when i > j. Inverting a measurement z with
// covariance Sigma gives z^-1 with covariance J Sigma J^T, J = d(z^-1)/dz at the measurement
// (first order). Only the ants need this chain; least squares and NLopt run on any connected
// graph (graph_optimize.hpp).

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

#include "antslam/slamgraph/fragment_set.hpp"

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
  std::vector<std::size_t> fixed{};  ///< vertices of FIX lines, ascending, each once; none: the
                                     ///< optimizers hold vertex 0 fixed
  bool vertices_from_file = true;    ///< false: the file had no vertex lines, and `vertices` were
                                     ///< composed along the edges (spanning_tree_poses)
};

/// Reads g2o and TORO lines (above). Throws std::runtime_error "source:line: problem" on
/// unknown tags (3D types named as such), wrong field counts, non-numbers, non-finite values,
/// information matrices that are not positive definite, vertex ids that are not 0..n-1 exactly
/// once, edges to unknown vertices or to themselves, FIX of unknown vertices; "source: problem"
/// for a file without vertices whose edges leave an id out or do not join every vertex to
/// vertex 0.
PoseGraph read_g2o(std::istream& in, const std::string& source);
/// read_g2o of a file (g2o or TORO, whatever its name).
PoseGraph read_g2o_file(const std::filesystem::path& path);
/// Writes vertices, FIX lines, then edges with round-trip precision.
void write_g2o(std::ostream& out, const PoseGraph& graph);
/// Writes VERTEX2 and EDGE2 lines (and FIX lines, which TORO's own tools do not read, if the
/// graph fixes vertices) with round-trip precision.
void write_toro(std::ostream& out, const PoseGraph& graph);
/// Whether a file name is a pose graph's: .g2o or .graph (TORO).
bool is_pose_graph_file(const std::filesystem::path& path);
/// write_toro for a .graph name, write_g2o otherwise.
void write_pose_graph(std::ostream& out, const PoseGraph& graph, const std::filesystem::path& name);

struct G2oImportSettings {
  std::size_t samples = 20;  ///< M samples drawn per alignment (eq. 7)
  std::uint64_t seed = 1;    ///< seeds the samples
};

/// Returns a valid set (validate()). Throws std::invalid_argument naming `source` if some vertex
/// i >= 1 has no edge to i - 1 (the ants' samples are poses of vertex i in vertex i-1's frame),
/// if there is no closure, if an edge gives no Gaussian, or if the set is not valid.
FragmentSet fragment_set_from_g2o(const PoseGraph& graph, const G2oImportSettings& settings,
                                  const std::string& source);

/// The graph of a fragment set with the given world frames as vertices: alignments as edges
/// (i-1, i) with their means, closures as edges (a, b) with measurement H * anchor^-1.
PoseGraph pose_graph_of(const FragmentSet& set, std::span<const Pose2> frames);

/// Reference poses of a graph's vertices for evaluation: a pose graph file (.g2o, .graph: its
/// vertices), a TUM trajectory (.tum) or lines of `x y theta` (e.g. manhattan3500.gt.dat).
/// Throws std::runtime_error "source:line: problem".
std::vector<Pose2> read_reference_poses(const std::filesystem::path& path);

/// A fragment set from a file: fragment_set_from_g2o of a pose graph (.g2o, .graph), a
/// fragment-set JSON (fragment_set_io.hpp) otherwise.
FragmentSet read_optimizer_input(const std::filesystem::path& path,
                                 const G2oImportSettings& settings);

/// Reference poses of `count` fragments or vertices: `own` if `path` is empty, else
/// read_reference_poses(path). Throws std::runtime_error if the file's pose count is not `count`.
std::vector<Pose2> reference_poses(std::size_t count, std::span<const Pose2> own,
                                   const std::filesystem::path& path);

/// Reference poses of the set's fragments: reference_poses of its fragment count and its own
/// `reference`.
std::vector<Pose2> reference_frames(const FragmentSet& set, const std::filesystem::path& path);

/// The edge's measurement as a Gaussian over the pose of the other vertex in the frame of
/// vertex `from` (one of the edge's ends): inverted, to first order, when the edge is stored the
/// other way round.
Gaussian2 oriented(const PoseGraphEdge& edge, std::size_t from);

/// Covariance of z^-1 for z ~ N(measurement, covariance), to first order.
Eigen::Matrix3d inverse_covariance(const Pose2& measurement, const Eigen::Matrix3d& covariance);

}  // namespace antslam::slam
