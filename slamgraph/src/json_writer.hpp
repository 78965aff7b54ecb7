#pragma once
// Writing the JSON files: poses as [x, y, theta], Gaussians as mean + covariance, numbers with
// round-trip precision.

#include <nlohmann/json.hpp>
#include <ostream>
#include <span>

#include "antslam/slamgraph/gaussian2.hpp"
#include "antslam/slamgraph/pose2.hpp"

namespace antslam::slam::detail {

inline nlohmann::ordered_json pose_json(const Pose2& p) { return {p.x, p.y, p.theta}; }

inline nlohmann::ordered_json poses_json(std::span<const Pose2> poses) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const Pose2& p : poses) out.push_back(pose_json(p));
  return out;
}

inline nlohmann::ordered_json gaussian_json(const Gaussian2& g) {
  const Eigen::Matrix3d& c = g.covariance();
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (int r = 0; r < 3; ++r) rows.push_back({c(r, 0), c(r, 1), c(r, 2)});
  return {{"mean", pose_json(g.mean())}, {"covariance", rows}};
}

/// One member per line at the top, compact below: readable diffs, small files.
inline void write_json(std::ostream& out, const nlohmann::ordered_json& doc) {
  out << "{\n";
  bool first = true;
  for (const auto& [key, value] : doc.items()) {
    out << (first ? "" : ",\n") << "  " << nlohmann::ordered_json(key).dump() << ": ";
    if (value.is_array() && !value.empty()) {
      out << "[\n";
      for (std::size_t i = 0; i < value.size(); ++i)
        out << "    " << value[i].dump() << (i + 1 < value.size() ? ",\n" : "\n");
      out << "  ]";
    } else {
      out << value.dump();
    }
    first = false;
  }
  out << "\n}\n";
}

}  // namespace antslam::slam::detail
