#include "antslam/slamgraph/fragment_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace antslam::slam {

namespace {

/// Finite, and within kMaxCoordinate (the heading too: an angle of 1e9 rad is no angle).
bool finite(const Pose2& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.theta) &&
         std::max({std::abs(p.x), std::abs(p.y), std::abs(p.theta)}) <= kMaxCoordinate;
}

bool finite(const StampedPose& p) {
  return finite(p.pose) && std::isfinite(p.stamp) && std::abs(p.stamp) <= kMaxTimestamp;
}

/// Why a Gaussian of the set is unusable, or empty.
std::string gaussian_problem(const Gaussian2& g) {
  if (!finite(g.mean())) return ".mean is not finite or beyond 1e9";
  if (g.covariance().diagonal().maxCoeff() > kMaxVariance)
    return ".covariance has a variance above 1e18";
  if (g.information().diagonal().maxCoeff() > kMaxInformation)
    return ".covariance is too small (its inverse has an entry above 1e18)";
  return {};
}

[[noreturn]] void fail(const std::string& message) { throw std::invalid_argument(message); }

void check_choice(const FragmentSet& set, std::span<const std::uint32_t> choice) {
  if (choice.size() != set.layer_count())
    fail("choice has " + std::to_string(choice.size()) + " entries, expected " +
         std::to_string(set.layer_count()));
  for (std::size_t l = 0; l < choice.size(); ++l)
    if (choice[l] >= set.fragments[l + 1].samples.size())
      fail("choice[" + std::to_string(l) + "] = " + std::to_string(choice[l]) +
           " is not a sample of fragments[" + std::to_string(l + 1) + "]");
}

}  // namespace

void validate(const FragmentSet& set) {
  const std::size_t n = set.fragments.size();
  if (n < 2) fail("a fragment set needs at least 2 fragments, got " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i) {
    const Fragment& f = set.fragments[i];
    const std::string where = "fragments[" + std::to_string(i) + "]";
    if (!finite(f.exit)) fail(where + ".exit is not finite or beyond 1e9");
    for (std::size_t k = 0; k < f.trajectory.size(); ++k)
      if (!finite(f.trajectory[k]))
        fail(where + ".trajectory[" + std::to_string(k) + "] is not finite or beyond 1e9");
    if (i == 0) continue;
    if (!f.alignment) fail(where + ".alignment is missing");
    if (const std::string p = gaussian_problem(*f.alignment); !p.empty())
      fail(where + ".alignment" + p);
    if (f.samples.empty()) fail(where + ".samples is empty");
    if (f.samples.size() > std::numeric_limits<std::uint32_t>::max())
      fail(where + ".samples has more than 2^32 - 1 entries");
    for (std::size_t j = 0; j < f.samples.size(); ++j)
      if (!finite(f.samples[j]))
        fail(where + ".samples[" + std::to_string(j) + "] is not finite or beyond 1e9");
  }
  if (set.closures.empty()) fail("a fragment set needs at least one loop closure");
  for (std::size_t c = 0; c < set.closures.size(); ++c) {
    const LoopClosure& lc = set.closures[c];
    const std::string where = "closures[" + std::to_string(c) + "]";
    if (lc.to >= n) fail(where + ".to = " + std::to_string(lc.to) + " is out of range");
    if (lc.from >= lc.to) fail(where + ".from must be smaller than .to");
    if (!finite(lc.anchor)) fail(where + ".anchor is not finite or beyond 1e9");
    if (const std::string p = gaussian_problem(lc.hypothesis); !p.empty())
      fail(where + ".hypothesis" + p);
  }
  if (!set.reference.empty() && set.reference.size() != n)
    fail("reference has " + std::to_string(set.reference.size()) + " poses, expected " +
         std::to_string(n));
  for (std::size_t i = 0; i < set.reference.size(); ++i)
    if (!finite(set.reference[i]))
      fail("reference[" + std::to_string(i) + "] is not finite or beyond 1e9");
}

std::vector<Pose2> chosen_alignments(const FragmentSet& set,
                                     std::span<const std::uint32_t> choice) {
  check_choice(set, choice);
  std::vector<Pose2> alignments(choice.size());
  for (std::size_t l = 0; l < choice.size(); ++l)
    alignments[l] = set.fragments[l + 1].samples[choice[l]];
  return alignments;
}

std::vector<Pose2> mean_alignments(const FragmentSet& set) {
  std::vector<Pose2> alignments(set.layer_count());
  for (std::size_t l = 0; l < alignments.size(); ++l)
    alignments[l] = set.fragments[l + 1].alignment.value().mean();
  return alignments;
}

std::vector<Pose2> chain(std::span<const Pose2> alignments) {
  std::vector<Pose2> frames(alignments.size() + 1);
  for (std::size_t i = 1; i < frames.size(); ++i) frames[i] = frames[i - 1] * alignments[i - 1];
  return frames;
}

std::vector<Pose2> relative_alignments(std::span<const Pose2> frames) {
  std::vector<Pose2> alignments(frames.empty() ? 0 : frames.size() - 1);
  for (std::size_t i = 0; i < alignments.size(); ++i)
    alignments[i] = between(frames[i], frames[i + 1]);
  return alignments;
}

std::vector<Pose2> world_frames(const FragmentSet& set, std::span<const std::uint32_t> choice) {
  return chain(chosen_alignments(set, choice));
}

Pose2 closure_pose(const LoopClosure& c, std::span<const Pose2> frames) {
  return between(frames[c.from], frames[c.to] * c.anchor);
}

Scores score(const FragmentSet& set, std::span<const Pose2> alignments) {
  if (alignments.size() != set.layer_count())
    fail("got " + std::to_string(alignments.size()) + " alignments, expected " +
         std::to_string(set.layer_count()));
  Scores s;
  const auto add = [&s](const Gaussian2& g, const Pose2& p) {
    const double m = g.mahalanobis_squared(p);
    s.chi2 += m;
    s.weight += 1.0 - std::exp(-0.5 * m);
  };
  for (std::size_t i = 1; i < set.fragments.size(); ++i)
    add(*set.fragments[i].alignment, alignments[i - 1]);
  const std::vector<Pose2> frames = chain(alignments);
  for (const LoopClosure& c : set.closures) add(c.hypothesis, closure_pose(c, frames));
  return s;
}

double path_weight(const FragmentSet& set, std::span<const std::uint32_t> choice) {
  return score(set, chosen_alignments(set, choice)).weight;
}

Trajectory world_trajectory(const FragmentSet& set, std::span<const Pose2> frames) {
  if (frames.size() != set.fragments.size())
    fail("got " + std::to_string(frames.size()) + " frames, expected " +
         std::to_string(set.fragments.size()));
  Trajectory out;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Trajectory& local = set.fragments[i].trajectory;
    if (local.empty()) out.push_back({static_cast<double>(i), frames[i]});
    for (const StampedPose& p : local) out.push_back({p.stamp, frames[i] * p.pose});
  }
  return out;
}

}  // namespace antslam::slam
