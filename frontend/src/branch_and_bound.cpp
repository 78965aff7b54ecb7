#include "antslam/frontend/branch_and_bound.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace antslam::frontend {

namespace {

struct Node {
  std::size_t rotation = 0;     ///< index into the rotated point sets
  std::int64_t dx = 0, dy = 0;  ///< translation in cells from the box centre
  double score = 0.0;           ///< bound (inner node) or score (leaf), summed over points
};

struct Rotated {
  double theta = 0.0;
  std::vector<std::int64_t> x, y;  ///< lattice cells of the points at the box centre translation
};

class Search {
 public:
  Search(const LikelihoodPyramid& pyramid, const SearchBox& box,
         const std::optional<Exclusion>& exclusion)
      : pyramid_(pyramid), box_(box), exclusion_(exclusion) {}

  std::vector<Rotated> rotations;
  std::int64_t reach_x = 0, reach_y = 0;
  double best = 0.0;  ///< summed score to beat
  std::optional<Node> found;

  double score(const Node& n, int level) const {
    const Rotated& r = rotations[n.rotation];
    double sum = 0.0;
    for (std::size_t j = 0; j < r.x.size(); ++j)
      sum += pyramid_.at(level, r.x[j] + n.dx, r.y[j] + n.dy);
    return sum;
  }

  slam::Pose2 pose(const Node& n) const {
    const double res = pyramid_.resolution();
    return {box_.center.x + static_cast<double>(n.dx) * res,
            box_.center.y + static_cast<double>(n.dy) * res, rotations[n.rotation].theta};
  }

  bool excluded(const Node& n) const {
    if (!exclusion_) return false;
    const slam::Pose2 p = pose(n);
    return std::abs(p.x - exclusion_->pose.x) <= exclusion_->linear &&
           std::abs(p.y - exclusion_->pose.y) <= exclusion_->linear &&
           std::abs(slam::wrap_angle(p.theta - exclusion_->pose.theta)) <= exclusion_->angular;
  }

  /// Depth-first over candidates sorted best first; stops at the first that cannot win.
  void descend(std::vector<Node>& nodes, int level) {
    std::stable_sort(nodes.begin(), nodes.end(),
                     [](const Node& a, const Node& b) { return a.score > b.score; });
    for (const Node& n : nodes) {
      if (n.score <= best) return;
      if (level == 0) {
        if (excluded(n)) continue;
        best = n.score;
        found = n;
        continue;
      }
      const std::int64_t half = std::int64_t{1} << (level - 1);
      std::vector<Node> children;
      for (const std::int64_t oy : {std::int64_t{0}, half})
        for (const std::int64_t ox : {std::int64_t{0}, half}) {
          Node c{n.rotation, n.dx + ox, n.dy + oy, 0.0};
          if (c.dx > reach_x || c.dy > reach_y) continue;
          c.score = score(c, level - 1);
          children.push_back(c);
        }
      descend(children, level - 1);
    }
  }

 private:
  const LikelihoodPyramid& pyramid_;
  const SearchBox& box_;
  const std::optional<Exclusion>& exclusion_;
};

}  // namespace

std::optional<ScoredPose> branch_and_bound(const LikelihoodPyramid& pyramid,
                                           std::span<const Eigen::Vector2d> points,
                                           const SearchBox& box, double min_score,
                                           const std::optional<Exclusion>& exclusion) {
  if (!(box.angular_step > 0.0) || !(box.angular >= 0.0) || !(box.linear_x >= 0.0) ||
      !(box.linear_y >= 0.0))
    throw std::invalid_argument("branch and bound: bad search box");
  if (points.empty()) return std::nullopt;
  Search search(pyramid, box, exclusion);
  const double res = pyramid.resolution();
  search.reach_x = static_cast<std::int64_t>(std::ceil(box.linear_x / res));
  search.reach_y = static_cast<std::int64_t>(std::ceil(box.linear_y / res));
  const auto turns = static_cast<std::int64_t>(std::floor(box.angular / box.angular_step));
  for (std::int64_t k = -turns; k <= turns; ++k) {
    Rotated r;
    r.theta = slam::wrap_angle(box.center.theta + static_cast<double>(k) * box.angular_step);
    const slam::Pose2 placed{box.center.x, box.center.y, r.theta};
    for (const Eigen::Vector2d& p : points) {
      const Eigen::Vector2d q = placed * p;
      r.x.push_back(pyramid.cell(q.x()));
      r.y.push_back(pyramid.cell(q.y()));
    }
    search.rotations.push_back(std::move(r));
  }
  // Root blocks of the top level tile the translation window.
  const int top = pyramid.levels() - 1;
  const std::int64_t step = std::int64_t{1} << top;
  std::vector<Node> roots;
  for (std::size_t rot = 0; rot < search.rotations.size(); ++rot)
    for (std::int64_t dy = -search.reach_y; dy <= search.reach_y; dy += step)
      for (std::int64_t dx = -search.reach_x; dx <= search.reach_x; dx += step) {
        Node n{rot, dx, dy, 0.0};
        n.score = search.score(n, top);
        roots.push_back(n);
      }
  search.best = min_score * static_cast<double>(points.size());
  search.descend(roots, top);
  if (!search.found) return std::nullopt;
  return ScoredPose{search.pose(*search.found),
                    search.found->score / static_cast<double>(points.size())};
}

double lattice_score(const LikelihoodPyramid& pyramid, std::span<const Eigen::Vector2d> points,
                     const slam::Pose2& pose) {
  if (points.empty()) return 0.0;
  double sum = 0.0;
  for (const Eigen::Vector2d& p : points) {
    const Eigen::Vector2d q = pose * p;
    sum += pyramid.at(0, pyramid.cell(q.x()), pyramid.cell(q.y()));
  }
  return sum / static_cast<double>(points.size());
}

}  // namespace antslam::frontend
