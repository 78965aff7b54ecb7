#include "slamgraph/g2o.hpp"

#include <Eigen/Cholesky>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include "aco/random.hpp"
#include "slamgraph/fragment_set_io.hpp"
#include "text_lines.hpp"

namespace antslam::slam {

namespace {

using detail::fail_at;

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

/// Inverse of a symmetric positive definite matrix (covariance <-> information), symmetrised.
Eigen::Matrix3d symmetric_inverse(const Eigen::Matrix3d& m) {
  const Eigen::LLT<Eigen::Matrix3d> llt(m);
  Eigen::Matrix3d c = llt.solve(Eigen::Matrix3d::Identity());
  return 0.5 * (c + c.transpose());
}

/// Jacobian of q = p * b with respect to p (b constant).
Eigen::Matrix3d right_compose_jacobian(const Pose2& p, const Pose2& b) {
  const Eigen::Vector2d rotated = Pose2{0.0, 0.0, p.theta} * b.translation();
  Eigen::Matrix3d j = Eigen::Matrix3d::Identity();
  j(0, 2) = -rotated.y();
  j(1, 2) = rotated.x();
  return j;
}

}  // namespace

PoseGraph read_g2o(std::istream& in, const std::string& source) {
  std::map<std::uint64_t, std::pair<Pose2, std::size_t>> vertices;  // id -> (pose, line)
  std::vector<std::pair<PoseGraphEdge, std::size_t>> edges;         // (edge, line)
  detail::for_each_data_line(in, source, [&](std::istringstream& fields, std::size_t line) {
    std::string tag;
    fields >> tag;
    if (tag == "VERTEX_SE2") {
      const std::uint64_t id = vertex_id(fields, source, line);
      const auto v = numbers(fields, 3, source, line, "VERTEX_SE2 id x y theta");
      const auto [it, added] =
          vertices.try_emplace(id, Pose2::from_vector({v[0], v[1], v[2]}), line);
      if (!added)
        fail_at(source, line,
                "vertex " + std::to_string(id) + " already defined on line " +
                    std::to_string(it->second.second));
    } else if (tag == "EDGE_SE2") {
      PoseGraphEdge e;
      e.from = vertex_id(fields, source, line);
      e.to = vertex_id(fields, source, line);
      const auto v =
          numbers(fields, 9, source, line, "EDGE_SE2 i j dx dy dtheta I11 I12 I13 I22 I23 I33");
      if (e.from == e.to) fail_at(source, line, "edge from a vertex to itself");
      e.measurement = Pose2::from_vector({v[0], v[1], v[2]});
      e.information << v[3], v[4], v[5], v[4], v[6], v[7], v[5], v[7], v[8];
      const Eigen::LLT<Eigen::Matrix3d> llt(e.information);
      if (llt.info() != Eigen::Success ||
          !(llt.matrixL().toDenseMatrix().diagonal().minCoeff() > 0.0))
        fail_at(source, line, "information matrix is not positive definite");
      edges.emplace_back(e, line);
    } else if (tag != "FIX") {  // FIX: the first vertex is always held fixed
      fail_at(source, line, "unsupported tag '" + tag + "' (expected VERTEX_SE2 or EDGE_SE2)");
    }
  });
  if (vertices.empty()) throw std::runtime_error(source + ": no VERTEX_SE2 lines");
  PoseGraph graph;
  for (const auto& [id, vertex] : vertices) {
    if (id != graph.vertices.size())
      throw std::runtime_error(source + ": vertex ids must be 0..n-1; vertex " +
                               std::to_string(graph.vertices.size()) + " is missing");
    graph.vertices.push_back(vertex.first);
  }
  for (const auto& [edge, line] : edges) {
    if (edge.from >= graph.vertices.size() || edge.to >= graph.vertices.size())
      fail_at(source, line, "edge to an undefined vertex");
    graph.edges.push_back(edge);
  }
  return graph;
}

PoseGraph read_g2o_file(const std::filesystem::path& path) {
  std::ifstream in = detail::open_input(path);
  return read_g2o(in, path.string());
}

void write_g2o(std::ostream& out, const PoseGraph& graph) {
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  for (std::size_t i = 0; i < graph.vertices.size(); ++i) {
    const Pose2& p = graph.vertices[i];
    out << "VERTEX_SE2 " << i << ' ' << p.x << ' ' << p.y << ' ' << p.theta << '\n';
  }
  for (const PoseGraphEdge& e : graph.edges) {
    const Pose2& z = e.measurement;
    const Eigen::Matrix3d& w = e.information;
    out << "EDGE_SE2 " << e.from << ' ' << e.to << ' ' << z.x << ' ' << z.y << ' ' << z.theta << ' '
        << w(0, 0) << ' ' << w(0, 1) << ' ' << w(0, 2) << ' ' << w(1, 1) << ' ' << w(1, 2) << ' '
        << w(2, 2) << '\n';
  }
}

Eigen::Matrix3d inverse_covariance(const Pose2& z, const Eigen::Matrix3d& covariance) {
  const double c = std::cos(z.theta), s = std::sin(z.theta);
  Eigen::Matrix3d j;  // d(z^-1)/dz, z^-1 = (-c x - s y, s x - c y, -theta)
  j << -c, -s, s * z.x - c * z.y, s, -c, c * z.x + s * z.y, 0.0, 0.0, -1.0;
  const Eigen::Matrix3d out = j * covariance * j.transpose();
  return 0.5 * (out + out.transpose());
}

Gaussian2 oriented(const PoseGraphEdge& edge, std::size_t from) {
  const Eigen::Matrix3d covariance = symmetric_inverse(edge.information);
  if (edge.from == from) return Gaussian2(edge.measurement, covariance);
  return Gaussian2(edge.measurement.inverse(), inverse_covariance(edge.measurement, covariance));
}

FragmentSet fragment_set_from_g2o(const PoseGraph& graph, const G2oImportSettings& settings,
                                  const std::string& source) {
  if (settings.samples == 0) throw std::invalid_argument("g2o import: samples must be >= 1");
  const std::size_t n = graph.vertices.size();
  if (n < 2) throw std::invalid_argument(source + ": a pose graph needs at least 2 vertices");
  FragmentSet set;
  set.name = source;
  set.fragments.resize(n);
  const auto oriented_from = [&source](const PoseGraphEdge& e, std::size_t a) {
    try {
      return oriented(e, a);
    } catch (const std::invalid_argument& problem) {
      throw std::invalid_argument(source + ": EDGE_SE2 " + std::to_string(e.from) + " " +
                                  std::to_string(e.to) + ": as a Gaussian from vertex " +
                                  std::to_string(a) + ", " + problem.what());
    }
  };
  for (const PoseGraphEdge& e : graph.edges) {
    const std::size_t a = std::min(e.from, e.to), b = std::max(e.from, e.to);
    Fragment& f = set.fragments[b];
    if (b == a + 1 && !f.alignment) {
      f.alignment = oriented_from(e, a);
    } else {
      set.closures.push_back({a, b, Pose2{}, oriented_from(e, a)});
    }
  }
  aco::Rng rng(aco::mix_seed(settings.seed, 0x6207));
  for (std::size_t i = 1; i < n; ++i) {
    Fragment& f = set.fragments[i];
    if (!f.alignment)
      throw std::invalid_argument(source + ": no edge between vertices " + std::to_string(i - 1) +
                                  " and " + std::to_string(i) +
                                  " (the graph must chain consecutive poses)");
    for (std::size_t j = 0; j < settings.samples; ++j)
      f.samples.push_back(f.alignment->sample(rng));
    set.fragments[i - 1].exit = f.alignment->mean();
  }
  if (set.closures.empty())
    throw std::invalid_argument(source + ": the pose graph has no loop-closure edge");
  try {
    validate(set);  // e.g. an edge's measurement beyond kMaxCoordinate, now a fragment's exit
  } catch (const std::invalid_argument& problem) {
    throw std::invalid_argument(source + ": " + problem.what());
  }
  return set;
}

PoseGraph pose_graph_of(const FragmentSet& set, std::span<const Pose2> frames) {
  validate(set);
  if (frames.size() != set.fragments.size())
    throw std::invalid_argument("pose_graph_of: got " + std::to_string(frames.size()) +
                                " frames, expected " + std::to_string(set.fragments.size()));
  PoseGraph graph;
  graph.vertices.assign(frames.begin(), frames.end());
  for (std::size_t i = 1; i < set.fragments.size(); ++i) {
    const Gaussian2& g = *set.fragments[i].alignment;
    graph.edges.push_back({i - 1, i, g.mean(), g.information()});
  }
  for (const LoopClosure& c : set.closures) {
    // The closure says F_b A ~ H in F_a, i.e. F_b ~ H A^-1.
    const Pose2 anchor_inverse = c.anchor.inverse();
    const Eigen::Matrix3d j = right_compose_jacobian(c.hypothesis.mean(), anchor_inverse);
    const Eigen::Matrix3d cov = j * c.hypothesis.covariance() * j.transpose();
    graph.edges.push_back({c.from, c.to, c.hypothesis.mean() * anchor_inverse,
                           symmetric_inverse(0.5 * (cov + cov.transpose()))});
  }
  return graph;
}

std::vector<Pose2> read_reference_poses(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".g2o") return read_g2o_file(path).vertices;
  if (ext == ".tum") {
    std::vector<Pose2> poses;
    for (const StampedPose& p : read_tum_file(path)) poses.push_back(p.pose);
    return poses;
  }
  std::ifstream in = detail::open_input(path);
  return read_pose_lines(in, path.string());
}

FragmentSet read_optimizer_input(const std::filesystem::path& path,
                                 const G2oImportSettings& settings) {
  if (path.extension() != ".g2o") return read_fragment_set_file(path);
  return fragment_set_from_g2o(read_g2o_file(path), settings, path.string());
}

std::vector<Pose2> reference_frames(const FragmentSet& set, const std::filesystem::path& path) {
  if (path.empty()) return set.reference;
  std::vector<Pose2> poses = read_reference_poses(path);
  if (poses.size() != set.fragments.size())
    throw std::runtime_error(path.string() + ": has " + std::to_string(poses.size()) +
                             " poses, the fragment set " + std::to_string(set.fragments.size()));
  return poses;
}

}  // namespace antslam::slam
