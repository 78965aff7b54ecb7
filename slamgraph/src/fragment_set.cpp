#include "slamgraph/fragment_set.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace antslam::slam {

namespace {

bool finite(const Pose2& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.theta);
}

[[noreturn]] void fail(const std::string& message) { throw std::invalid_argument(message); }

}  // namespace

void validate(const FragmentSet& set) {
  const std::size_t n = set.fragments.size();
  if (n < 2) fail("a fragment set needs at least 2 fragments, got " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i) {
    const Fragment& f = set.fragments[i];
    const std::string where = "fragments[" + std::to_string(i) + "]";
    if (!finite(f.exit)) fail(where + ".exit is not finite");
    if (i == 0) continue;
    if (!f.alignment) fail(where + ".alignment is missing");
    if (f.samples.empty()) fail(where + ".samples is empty");
    for (std::size_t j = 0; j < f.samples.size(); ++j)
      if (!finite(f.samples[j])) fail(where + ".samples[" + std::to_string(j) + "] is not finite");
  }
  if (set.closures.empty()) fail("a fragment set needs at least one loop closure");
  for (std::size_t c = 0; c < set.closures.size(); ++c) {
    const LoopClosure& lc = set.closures[c];
    const std::string where = "closures[" + std::to_string(c) + "]";
    if (lc.to >= n) fail(where + ".to = " + std::to_string(lc.to) + " is out of range");
    if (lc.from >= lc.to) fail(where + ".from must be smaller than .to");
    if (!finite(lc.anchor)) fail(where + ".anchor is not finite");
  }
}

std::vector<Pose2> world_frames(const FragmentSet& set, std::span<const std::uint32_t> choice) {
  if (choice.size() + 1 != set.fragments.size())
    throw std::invalid_argument("choice has " + std::to_string(choice.size()) +
                                " entries, expected " + std::to_string(set.layer_count()));
  std::vector<Pose2> frames(set.fragments.size());
  for (std::size_t i = 1; i < frames.size(); ++i)
    frames[i] = frames[i - 1] * set.fragments[i].samples.at(choice[i - 1]);
  return frames;
}

Pose2 closure_pose(const LoopClosure& c, std::span<const Pose2> frames) {
  return between(frames[c.from], frames[c.to] * c.anchor);
}

double path_weight(const FragmentSet& set, std::span<const std::uint32_t> choice) {
  const std::vector<Pose2> frames = world_frames(set, choice);
  double weight = 0.0;
  for (std::size_t i = 1; i < set.fragments.size(); ++i) {
    const Fragment& f = set.fragments[i];
    weight += 1.0 - f.alignment->value(f.samples[choice[i - 1]]);
  }
  for (const LoopClosure& c : set.closures)
    weight += 1.0 - c.hypothesis.value(closure_pose(c, frames));
  return weight;
}

}  // namespace antslam::slam
