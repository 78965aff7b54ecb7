#include "antslam/eval/relations_error.hpp"

#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "antslam/eval/association.hpp"
#include "antslam/eval/detail/validation.hpp"
#include "antslam/eval/relative_error.hpp"

namespace antslam::eval {

RelationsResult relations_error(const slam::Trajectory& estimate,
                                std::span<const Relation> relations, double max_dt) {
  detail::check_max_dt(max_dt);
  detail::check_sorted(estimate, "estimate");
  std::vector<double> translation, translation_squared, rotation, rotation_squared;
  RelationsResult result;
  for (const Relation& relation : relations) {
    const std::optional<std::size_t> i = find_stamp(estimate, relation.stamp1, max_dt);
    const std::optional<std::size_t> j = find_stamp(estimate, relation.stamp2, max_dt);
    if (!i || !j) {
      ++result.skipped;
      continue;
    }
    // Kuemmerle et al. 2009, eq. (1): the error of delta_ij against delta*_ij.
    const RelativeError e = relative_error(estimate[*i].pose, estimate[*j].pose, relation.motion);
    translation.push_back(e.translation);
    translation_squared.push_back(e.translation * e.translation);
    rotation.push_back(degrees(e.rotation));
    rotation_squared.push_back(rotation.back() * rotation.back());
  }
  result.used = translation.size();
  if (result.used == 0) {
    std::ostringstream message;
    message << "relations: none of the " << relations.size()
            << " relations has both stamps in the estimate within max_dt = " << max_dt << " s";
    throw std::invalid_argument(message.str());
  }
  result.translation_m = mean_std(translation);
  result.translation_squared_m2 = mean_std(translation_squared);
  result.rotation_deg = mean_std(rotation);
  result.rotation_squared_deg2 = mean_std(rotation_squared);
  return result;
}

}  // namespace antslam::eval
