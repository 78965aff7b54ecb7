#include "antslam/slamgraph/outliers.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <ostream>
#include <stdexcept>

#include "antslam/aco/random.hpp"
#include "antslam/slamgraph/gaussian2.hpp"
#include "antslam/slamgraph/name_table.hpp"
#include "text_lines.hpp"

namespace antslam::slam {

std::string_view to_string(OutlierKind kind) { return detail::name_in(kOutlierKinds, kind); }

std::optional<OutlierKind> parse_outlier_kind(std::string_view name) {
  return detail::value_in(kOutlierKinds, name);
}

SpoiledGraph add_outliers(const PoseGraph& graph, const OutlierSettings& s) {
  const bool grouped = s.kind == OutlierKind::random_group || s.kind == OutlierKind::local_group;
  const bool local = s.kind == OutlierKind::local || s.kind == OutlierKind::local_group;
  const std::size_t group = grouped ? s.group_size : 1;
  if (group == 0) throw std::invalid_argument("outliers: group size must be >= 1");
  if (local && s.local_window < 2)
    throw std::invalid_argument("outliers: the local window must be >= 2 vertices");
  if (!(std::isfinite(s.sigma_xy) && s.sigma_xy >= 0.0 && std::isfinite(s.sigma_theta) &&
        s.sigma_theta >= 0.0))
    throw std::invalid_argument("outliers: the measurement deviations must be finite and >= 0");
  if (!(std::isfinite(s.information) && s.information > 0.0))
    throw std::invalid_argument("outliers: the information must be a finite positive number");
  const std::size_t n = graph.vertices.size();
  if (n < group + 3)
    throw std::invalid_argument("outliers: the graph has " + std::to_string(n) +
                                " vertices, groups of " + std::to_string(group) + " need " +
                                std::to_string(group + 3));
  // The first vertex of a group leaves room for the group: v + group - 1 <= n - 1.
  const auto last = static_cast<std::uint32_t>(n - 1 - group);
  aco::Rng rng(aco::mix_seed(s.seed, 0x0F1E5));
  SpoiledGraph out{graph, {}};
  for (std::size_t added = 0; added < s.count;) {
    std::size_t v1 = 0, v2 = 0;
    while (v1 == v2) {
      v1 = rng.below(last + 1);
      if (local) {
        const std::size_t top = std::min<std::size_t>(last, v1 + s.local_window);
        v2 = v1 + rng.below(static_cast<std::uint32_t>(top - v1 + 1));
      } else {
        v2 = rng.below(last + 1);
      }
      if (v1 > v2) std::swap(v1, v2);
      if (v2 == v1 + 1) v2 = v1 + 2;  // consecutive vertices would be odometry
    }
    const Pose2 z{s.sigma_xy * standard_normal(rng), s.sigma_xy * standard_normal(rng),
                  wrap_angle(s.sigma_theta * standard_normal(rng))};
    for (std::size_t j = 0; j < group && added < s.count; ++j, ++added) {
      out.graph.edges.push_back({v1 + j, v2 + j, z, s.information * Eigen::Matrix3d::Identity()});
      out.outliers.emplace_back(v1 + j, v2 + j);
    }
  }
  return out;
}

void write_outlier_pairs(std::ostream& out,
                         const std::vector<std::pair<std::size_t, std::size_t>>& outliers) {
  for (const auto& [i, j] : outliers) out << i << ' ' << j << '\n';
}

std::vector<bool> read_outlier_flags(const std::filesystem::path& path, const PoseGraph& graph,
                                     const ChainSplit& split) {
  std::ifstream in(path);
  const std::string source = path.string();
  if (!in) throw std::runtime_error(source + ": cannot open");
  struct Listed {
    std::size_t i, j, line;
  };
  std::vector<Listed> listed;
  detail::for_each_data_line(in, source, [&](std::istringstream& fields, std::size_t line) {
    std::uint64_t ids[2] = {0, 0};
    std::string token;
    for (std::uint64_t& id : ids) {
      if (!(fields >> token)) detail::fail_at(source, line, "expected `i j`");
      if (!detail::parse_index(token, id))
        detail::fail_at(source, line, "'" + token + "' is not a vertex id");
    }
    if (fields >> token) detail::fail_at(source, line, "expected `i j`");
    listed.push_back({ids[0], ids[1], line});
  });
  std::vector<bool> outlier(split.closures.size(), false);
  for (auto l = listed.rbegin(); l != listed.rend(); ++l) {
    bool found = false;
    for (std::size_t c = split.closures.size(); c-- > 0 && !found;) {
      const PoseGraphEdge& e = graph.edges[split.closures[c]];
      const bool same = (e.from == l->i && e.to == l->j) || (e.from == l->j && e.to == l->i);
      if (same && !outlier[c]) found = outlier[c] = true;
    }
    if (!found)
      detail::fail_at(source, l->line,
                      std::to_string(l->i) + " " + std::to_string(l->j) +
                          " is not a loop closure of the graph (or is listed more often)");
  }
  return outlier;
}

std::filesystem::path outliers_path_of(const std::filesystem::path& graph_path) {
  std::filesystem::path p = graph_path;
  return p.replace_extension(".outliers.txt");
}

}  // namespace antslam::slam
