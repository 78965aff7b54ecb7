#include "antslam/eval/ate.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "antslam/eval/alignment.hpp"
#include "antslam/eval/relative_error.hpp"

namespace antslam::eval {

AteResult ate(std::span<const PosePair> pairs, const slam::Pose2& alignment) {
  if (pairs.empty()) throw std::invalid_argument("ATE: no associated poses");
  std::vector<double> translation, rotation;
  translation.reserve(pairs.size());
  rotation.reserve(pairs.size());
  for (const PosePair& p : pairs) {
    const slam::Pose2 error = slam::between(p.reference, alignment * p.estimate);
    translation.push_back(error.translation().norm());
    rotation.push_back(degrees(std::abs(error.theta)));
  }
  return {alignment, summarize(translation), summarize(rotation)};
}

AteResult indexed_ate(std::span<const slam::Pose2> estimate,
                      std::span<const slam::Pose2> reference) {
  if (estimate.size() != reference.size())
    throw std::invalid_argument("ATE: " + std::to_string(estimate.size()) + " poses against " +
                                std::to_string(reference.size()) + " reference poses");
  std::vector<PosePair> pairs;
  for (std::size_t i = 0; i < estimate.size(); ++i)
    pairs.push_back({i, i, static_cast<double>(i), estimate[i], reference[i]});
  return ate(pairs, align(pairs));
}

}  // namespace antslam::eval
