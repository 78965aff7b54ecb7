// Pose graphs and fragment sets, both ways: the ants' chain of a graph, and the graph of a set.

#include <Eigen/Cholesky>
#include <stdexcept>
#include <string>

#include "antslam/aco/random.hpp"
#include "antslam/slamgraph/fragment_set_io.hpp"
#include "antslam/slamgraph/g2o.hpp"

namespace antslam::slam {

namespace {

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
      throw std::invalid_argument(
          source + ": no edge between vertices " + std::to_string(i - 1) + " and " +
          std::to_string(i) +
          ": the ant methods need one between every two consecutive vertices (their samples "
          "are poses of vertex i in the frame of vertex i-1); ceres, ceres-robust and nlopt run "
          "on any connected graph");
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

FragmentSet read_optimizer_input(const std::filesystem::path& path,
                                 const G2oImportSettings& settings) {
  if (!is_pose_graph_file(path)) return read_fragment_set_file(path);
  return fragment_set_from_g2o(read_g2o_file(path), settings, path.string());
}

std::vector<Pose2> reference_frames(const FragmentSet& set, const std::filesystem::path& path) {
  return reference_poses(set.fragments.size(), set.reference, path);
}

}  // namespace antslam::slam
