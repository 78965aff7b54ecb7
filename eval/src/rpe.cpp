#include "antslam/eval/rpe.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "antslam/eval/relative_error.hpp"

namespace antslam::eval {

namespace {

/// step[i] = index of the partner of pair i, or pairs.size() if it has none.
std::vector<std::size_t> partners(std::span<const PosePair> pairs, const RpeSettings& settings) {
  std::vector<std::size_t> partner(pairs.size(), pairs.size());
  if (settings.metres == 0.0) {
    for (std::size_t i = 0; i + settings.frames < pairs.size(); ++i)
      partner[i] = i + settings.frames;
    return partner;
  }
  std::vector<double> travelled(pairs.size(), 0.0);  // along the reference, from pair 0
  for (std::size_t k = 1; k < pairs.size(); ++k)
    travelled[k] = travelled[k - 1] +
                   (pairs[k].reference.translation() - pairs[k - 1].reference.translation()).norm();
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const auto j = std::partition_point(
        travelled.begin() + static_cast<std::ptrdiff_t>(i) + 1, travelled.end(),
        [&](double length) { return length - travelled[i] < settings.metres; });
    partner[i] = static_cast<std::size_t>(j - travelled.begin());
  }
  return partner;
}

std::string describe(const RpeSettings& settings) {
  std::ostringstream text;
  if (settings.metres > 0.0)
    text << settings.metres << " m";
  else
    text << settings.frames << (settings.frames == 1 ? " frame" : " frames");
  return text.str();
}

}  // namespace

RpeResult rpe(std::span<const PosePair> pairs, const RpeSettings& settings) {
  if (!std::isfinite(settings.metres) || settings.metres < 0.0)
    throw std::invalid_argument("RPE distance must be a finite number >= 0 metres");
  if (settings.metres == 0.0 && settings.frames == 0)
    throw std::invalid_argument("RPE frame step must be at least 1");
  const std::vector<std::size_t> partner = partners(pairs, settings);
  std::vector<double> translation, rotation;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::size_t j = partner[i];
    if (j == pairs.size()) continue;
    const slam::Pose2 reference_motion = slam::between(pairs[i].reference, pairs[j].reference);
    const RelativeError e = relative_error(pairs[i].estimate, pairs[j].estimate, reference_motion);
    translation.push_back(e.translation);
    rotation.push_back(degrees(e.rotation));
  }
  if (translation.empty())
    throw std::invalid_argument("RPE: no two of the " + std::to_string(pairs.size()) +
                                " associated poses are " + describe(settings) + " apart");
  return {settings, summarize(translation), summarize(rotation)};
}

}  // namespace antslam::eval
