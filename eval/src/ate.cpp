#include "eval/ate.hpp"

#include <stdexcept>
#include <vector>

#include "eval/relative_error.hpp"

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

}  // namespace antslam::eval
