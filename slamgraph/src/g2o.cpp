#include "slamgraph/g2o.hpp"

#include <Eigen/Cholesky>
#include <charconv>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "aco/random.hpp"

namespace antslam::slam {

namespace {

[[noreturn]] void fail(const std::string& source, std::size_t line, const std::string& problem) {
  throw std::runtime_error(source + ":" + std::to_string(line) + ": " + problem);
}

/// The remaining fields of a line as exactly `count` finite numbers.
std::vector<double> numbers(std::istringstream& fields, std::size_t count,
                            const std::string& source, std::size_t line, const char* layout) {
  std::vector<double> v;
  std::string token;
  while (fields >> token) {
    double x = 0.0;
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, x);
    if (ec != std::errc() || ptr != end) fail(source, line, "'" + token + "' is not a number");
    if (!std::isfinite(x)) fail(source, line, "non-finite number");
    v.push_back(x);
  }
  if (v.size() != count) fail(source, line, std::string("expected ") + layout);
  return v;
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
  PoseGraph graph;
  std::vector<std::size_t> vertex_line;
  struct Pending {
    PoseGraphEdge edge;
    std::size_t line;
  };
  std::vector<Pending> edges;
  std::string text;
  std::size_t line = 0;
  while (std::getline(in, text)) {
    ++line;
    std::istringstream fields(text);
    std::string tag;
    if (!(fields >> tag) || tag[0] == '#') continue;
    if (tag == "VERTEX_SE2") {
      std::size_t id = 0;
      if (!(fields >> id)) fail(source, line, "expected a vertex id");
      const auto v = numbers(fields, 3, source, line, "VERTEX_SE2 id x y theta");
      if (id >= graph.vertices.size()) {
        graph.vertices.resize(id + 1, Pose2{std::numeric_limits<double>::quiet_NaN()});
        vertex_line.resize(id + 1, 0);
      }
      if (vertex_line[id] != 0)
        fail(source, line,
             "vertex " + std::to_string(id) + " already defined on line " +
                 std::to_string(vertex_line[id]));
      graph.vertices[id] = Pose2::from_vector({v[0], v[1], v[2]});
      vertex_line[id] = line;
    } else if (tag == "EDGE_SE2") {
      PoseGraphEdge e;
      if (!(fields >> e.from >> e.to)) fail(source, line, "expected two vertex ids");
      const auto v =
          numbers(fields, 9, source, line, "EDGE_SE2 i j dx dy dtheta I11 I12 I13 I22 I23 I33");
      if (e.from == e.to) fail(source, line, "edge from a vertex to itself");
      e.measurement = Pose2::from_vector({v[0], v[1], v[2]});
      e.information << v[3], v[4], v[5], v[4], v[6], v[7], v[5], v[7], v[8];
      const Eigen::LLT<Eigen::Matrix3d> llt(e.information);
      if (llt.info() != Eigen::Success ||
          !(llt.matrixL().toDenseMatrix().diagonal().minCoeff() > 0.0))
        fail(source, line, "information matrix is not positive definite");
      edges.push_back({e, line});
    } else if (tag == "FIX") {
      continue;  // the first vertex is always held fixed
    } else {
      fail(source, line, "unsupported tag '" + tag + "' (expected VERTEX_SE2 or EDGE_SE2)");
    }
  }
  if (in.bad()) throw std::runtime_error(source + ": read error");
  for (std::size_t id = 0; id < vertex_line.size(); ++id)
    if (vertex_line[id] == 0)
      throw std::runtime_error(source + ": vertex ids must be 0..n-1; vertex " +
                               std::to_string(id) + " is missing");
  if (graph.vertices.empty()) throw std::runtime_error(source + ": no VERTEX_SE2 lines");
  for (const Pending& p : edges) {
    if (p.edge.from >= graph.vertices.size() || p.edge.to >= graph.vertices.size())
      fail(source, p.line, "edge to an undefined vertex");
    graph.edges.push_back(p.edge);
  }
  return graph;
}

PoseGraph read_g2o_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
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

FragmentSet fragment_set_from_g2o(const PoseGraph& graph, const G2oImportSettings& settings,
                                  const std::string& source) {
  if (settings.samples == 0) throw std::invalid_argument("g2o import: samples must be >= 1");
  const std::size_t n = graph.vertices.size();
  if (n < 2) throw std::invalid_argument(source + ": a pose graph needs at least 2 vertices");
  FragmentSet set;
  set.name = source;
  set.fragments.resize(n);
  const auto oriented = [](const PoseGraphEdge& e, std::size_t a) {
    const Eigen::Matrix3d cov = symmetric_inverse(e.information);
    if (e.from == a) return Gaussian2(e.measurement, cov);
    return Gaussian2(e.measurement.inverse(), inverse_covariance(e.measurement, cov));
  };
  for (const PoseGraphEdge& e : graph.edges) {
    const std::size_t a = std::min(e.from, e.to), b = std::max(e.from, e.to);
    Fragment& f = set.fragments[b];
    if (b == a + 1 && !f.alignment) {
      f.alignment = oriented(e, a);
    } else {
      set.closures.push_back({a, b, Pose2{}, oriented(e, a)});
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

}  // namespace antslam::slam
