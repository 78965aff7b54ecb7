#include "antslam/slamgraph/g2o.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "antslam/slamgraph/graph_structure.hpp"
#include "text_lines.hpp"

namespace antslam::slam {

namespace {

using detail::fail_at;

constexpr const char* kTags = "VERTEX_SE2, EDGE_SE2, VERTEX2, EDGE2 or FIX";

/// The remaining fields of a line as exactly `count` finite numbers.
std::vector<double> numbers(std::istringstream& fields, std::size_t count,
                            const std::string& source, std::size_t line, const char* layout) {
  std::vector<double> v;
  std::string token;
  while (fields >> token) {
    double x = 0.0;
    if (!detail::parse_number(token, x)) fail_at(source, line, "'" + token + "' is not a number");
    if (!std::isfinite(x)) fail_at(source, line, "non-finite number");
    v.push_back(x);
  }
  if (v.size() != count) fail_at(source, line, std::string("expected ") + layout);
  return v;
}

/// The next field as a vertex id (a non-negative integer).
std::uint64_t vertex_id(std::istringstream& fields, const std::string& source, std::size_t line) {
  std::string token;
  std::uint64_t id = 0;
  if (fields >> token && detail::parse_index(token, id)) return id;
  fail_at(source, line, "'" + token + "' is not a vertex id");
}

/// Lines of `x y theta` ('#' comments and blank lines skipped).
std::vector<Pose2> read_pose_lines(std::istream& in, const std::string& source) {
  std::vector<Pose2> poses;
  detail::for_each_data_line(in, source, [&](std::istringstream& fields, std::size_t line) {
    const auto v = numbers(fields, 3, source, line, "`x y theta`");
    poses.push_back(Pose2::from_vector({v[0], v[1], v[2]}));
  });
  return poses;
}

/// Tags of 3D graphs (g2o's SE(3) and point types, TORO's 3D lines).
bool is_3d_tag(std::string_view tag) {
  return tag.find("SE3") != std::string_view::npos || tag.find("XYZ") != std::string_view::npos ||
         tag == "VERTEX3" || tag == "EDGE3";
}

/// An edge line after its tag; `toro` reads TORO's order of the information entries.
PoseGraphEdge read_edge(std::istringstream& fields, bool toro, const std::string& source,
                        std::size_t line) {
  PoseGraphEdge e;
  e.from = vertex_id(fields, source, line);
  e.to = vertex_id(fields, source, line);
  const auto v = numbers(fields, 9, source, line,
                         toro ? "EDGE2 i j dx dy dtheta Ixx Ixy Iyy Itt Ixt Iyt"
                              : "EDGE_SE2 i j dx dy dtheta I11 I12 I13 I22 I23 I33");
  if (e.from == e.to) fail_at(source, line, "edge from a vertex to itself");
  e.measurement = Pose2::from_vector({v[0], v[1], v[2]});
  // Upper-triangle entries (xx, xy, xt, yy, yt, tt) at these positions of v.
  const std::array<int, 6> at = toro ? std::array{3, 4, 7, 5, 8, 6} : std::array{3, 4, 5, 6, 7, 8};
  const auto w = [&](int k) {
    return v[static_cast<std::size_t>(at[static_cast<std::size_t>(k)])];
  };
  e.information << w(0), w(1), w(2), w(1), w(3), w(4), w(2), w(4), w(5);
  const Eigen::LLT<Eigen::Matrix3d> llt(e.information);
  if (llt.info() != Eigen::Success || !(llt.matrixL().toDenseMatrix().diagonal().minCoeff() > 0.0))
    fail_at(source, line, "information matrix is not positive definite");
  // The fragment sets' bound (a standard deviation of 1e-9): beyond it the optimizers' weights
  // and kernel widths over- and underflow.
  if (e.information.diagonal().maxCoeff() > kMaxInformation)
    fail_at(source, line,
            "information matrix has an entry above 1e18 (a standard deviation below 1e-9)");
  return e;
}

/// The graph's vertex count when the file has no vertex lines: every id 0..n-1 must occur in an
/// edge.
std::size_t vertices_of_edges(const std::vector<std::pair<PoseGraphEdge, std::size_t>>& edges,
                              const std::string& source) {
  std::vector<bool> used;
  for (const auto& [e, line] : edges) {
    const std::size_t top = std::max(e.from, e.to);
    if (top >= std::size_t{1} << 26)
      fail_at(source, line,
              "vertex id " + std::to_string(top) +
                  " is too large for a graph "
                  "without vertex lines (ids must be 0..n-1)");
    if (top >= used.size()) used.resize(top + 1, false);
    used[e.from] = used[e.to] = true;
  }
  const auto missing = std::find(used.begin(), used.end(), false);
  if (missing != used.end())
    throw std::runtime_error(source + ": no vertex lines, and vertex " +
                             std::to_string(missing - used.begin()) +
                             " is in no edge (ids must be 0..n-1)");
  return used.size();
}

void write_lines(std::ostream& out, const PoseGraph& graph, bool toro) {
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  for (std::size_t i = 0; i < graph.vertices.size(); ++i) {
    const Pose2& p = graph.vertices[i];
    out << (toro ? "VERTEX2 " : "VERTEX_SE2 ") << i << ' ' << p.x << ' ' << p.y << ' ' << p.theta
        << '\n';
  }
  for (const std::size_t v : graph.fixed) out << "FIX " << v << '\n';
  for (const PoseGraphEdge& e : graph.edges) {
    const Pose2& z = e.measurement;
    const Eigen::Matrix3d& w = e.information;
    out << (toro ? "EDGE2 " : "EDGE_SE2 ") << e.from << ' ' << e.to << ' ' << z.x << ' ' << z.y
        << ' ' << z.theta << ' ';
    if (toro) {
      out << w(0, 0) << ' ' << w(0, 1) << ' ' << w(1, 1) << ' ' << w(2, 2) << ' ' << w(0, 2) << ' '
          << w(1, 2) << '\n';
    } else {
      out << w(0, 0) << ' ' << w(0, 1) << ' ' << w(0, 2) << ' ' << w(1, 1) << ' ' << w(1, 2) << ' '
          << w(2, 2) << '\n';
    }
  }
}

}  // namespace

PoseGraph read_g2o(std::istream& in, const std::string& source) {
  std::map<std::uint64_t, std::pair<Pose2, std::size_t>> vertices;  // id -> (pose, line)
  std::vector<std::pair<PoseGraphEdge, std::size_t>> edges;         // (edge, line)
  std::vector<std::pair<std::uint64_t, std::size_t>> fixed;         // (id, line)
  detail::for_each_data_line(in, source, [&](std::istringstream& fields, std::size_t line) {
    std::string tag;
    fields >> tag;
    if (tag == "VERTEX_SE2" || tag == "VERTEX2") {
      const std::uint64_t id = vertex_id(fields, source, line);
      const auto v = numbers(fields, 3, source, line, "VERTEX_SE2 id x y theta");
      const auto [it, added] =
          vertices.try_emplace(id, Pose2::from_vector({v[0], v[1], v[2]}), line);
      if (!added)
        fail_at(source, line,
                "vertex " + std::to_string(id) + " already defined on line " +
                    std::to_string(it->second.second));
    } else if (tag == "EDGE_SE2" || tag == "EDGE2") {
      edges.emplace_back(read_edge(fields, tag == "EDGE2", source, line), line);
    } else if (tag == "FIX") {
      do {
        fixed.emplace_back(vertex_id(fields, source, line), line);
      } while (!(fields >> std::ws).eof());
    } else if (is_3d_tag(tag)) {
      fail_at(source, line,
              "'" + tag + "' is a 3D type; antslam reads 2D pose graphs (" + kTags + ")");
    } else {
      fail_at(source, line, "unsupported tag '" + tag + "' (expected " + kTags + ")");
    }
  });
  if (vertices.empty() && edges.empty())
    throw std::runtime_error(source + ": no vertices or edges");
  PoseGraph graph;
  graph.vertices_from_file = !vertices.empty();
  for (const auto& [id, vertex] : vertices) {
    if (id != graph.vertices.size())
      throw std::runtime_error(source + ": vertex ids must be 0..n-1; vertex " +
                               std::to_string(graph.vertices.size()) + " is missing");
    graph.vertices.push_back(vertex.first);
  }
  const std::size_t n =
      graph.vertices_from_file ? graph.vertices.size() : vertices_of_edges(edges, source);
  for (const auto& [edge, line] : edges) {
    if (edge.from >= n || edge.to >= n) fail_at(source, line, "edge to an undefined vertex");
    graph.edges.push_back(edge);
  }
  for (const auto& [id, line] : fixed) {
    if (id >= n) fail_at(source, line, "FIX of undefined vertex " + std::to_string(id));
    graph.fixed.push_back(id);
  }
  std::sort(graph.fixed.begin(), graph.fixed.end());
  graph.fixed.erase(std::unique(graph.fixed.begin(), graph.fixed.end()), graph.fixed.end());
  if (!graph.vertices_from_file) {
    graph.vertices.resize(n);
    graph.vertices = spanning_tree_poses(graph, source);
  }
  return graph;
}

PoseGraph read_g2o_file(const std::filesystem::path& path) {
  std::ifstream in = detail::open_input(path);
  return read_g2o(in, path.string());
}

void write_g2o(std::ostream& out, const PoseGraph& graph) { write_lines(out, graph, false); }

void write_toro(std::ostream& out, const PoseGraph& graph) { write_lines(out, graph, true); }

bool is_pose_graph_file(const std::filesystem::path& path) {
  return path.extension() == ".g2o" || path.extension() == ".graph";
}

void write_pose_graph(std::ostream& out, const PoseGraph& graph,
                      const std::filesystem::path& name) {
  write_lines(out, graph, name.extension() == ".graph");
}

std::vector<Pose2> read_reference_poses(const std::filesystem::path& path) {
  if (is_pose_graph_file(path)) return read_g2o_file(path).vertices;
  if (path.extension() == ".tum") {
    std::vector<Pose2> poses;
    for (const StampedPose& p : read_tum_file(path)) poses.push_back(p.pose);
    return poses;
  }
  std::ifstream in = detail::open_input(path);
  return read_pose_lines(in, path.string());
}

std::vector<Pose2> reference_poses(std::size_t count, std::span<const Pose2> own,
                                   const std::filesystem::path& path) {
  if (path.empty()) return {own.begin(), own.end()};
  std::vector<Pose2> poses = read_reference_poses(path);
  if (poses.size() != count)
    throw std::runtime_error(path.string() + ": has " + std::to_string(poses.size()) +
                             " poses, expected " + std::to_string(count));
  return poses;
}

}  // namespace antslam::slam
