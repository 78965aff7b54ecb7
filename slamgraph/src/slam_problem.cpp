#include "antslam/slamgraph/slam_problem.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace antslam::slam {

namespace {

using Frame = SlamProblem::Frame;

Frame to_frame(const Pose2& p) { return {p.x, p.y, std::cos(p.theta), std::sin(p.theta), p.theta}; }

/// a * b, eq. (8)'s product, without trigonometry.
inline Frame compose(const Frame& a, const Frame& b) {
  return {a.x + a.c * b.x - a.s * b.y, a.y + a.s * b.x + a.c * b.y, a.c * b.c - a.s * b.s,
          a.s * b.c + a.c * b.s, a.theta + b.theta};
}

/// Into [-pi, pi); chain angles are sums of wrapped angles, so this loops a few times at most.
inline double wrap(double a) {
  constexpr double kPi = std::numbers::pi, kTwoPi = 2.0 * std::numbers::pi;
  while (a >= kPi) a -= kTwoPi;
  while (a < -kPi) a += kTwoPi;
  return a;
}

}  // namespace

SlamProblem::SlamProblem(const FragmentSet& set) {
  validate(set);
  offset_.assign(1, 0);
  for (std::size_t i = 1; i < set.fragments.size(); ++i) {
    const Fragment& f = set.fragments[i];
    for (const Pose2& s : f.samples) samples_.push_back({to_frame(s), 1.0 - f.alignment->value(s)});
    offset_.push_back(samples_.size());
  }
  std::map<std::size_t, Event> events;
  for (std::uint32_t k = 0; k < set.closures.size(); ++k) {
    const LoopClosure& c = set.closures[k];
    Closure closure{};
    closure.from_world = c.from == 0;
    closure.slot = static_cast<std::uint32_t>(closure.from_world ? 0 : kept_frames_++);
    closure.anchor = to_frame(c.anchor);
    closure.mean = c.hypothesis.mean();
    const Eigen::Matrix3d& w = c.hypothesis.information();
    const double info[6] = {w(0, 0), w(0, 1), w(0, 2), w(1, 1), w(1, 2), w(2, 2)};
    std::copy(std::begin(info), std::end(info), std::begin(closure.info));
    closures_.push_back(closure);
    if (!closure.from_world) events[c.from].opening.push_back(k);
    events[c.to].closing.push_back(k);
  }
  for (auto& [fragment, event] : events) {
    event.fragment = fragment;
    events_.push_back(std::move(event));
  }
}

double SlamProblem::closure_term(const Closure& c, const Frame& from, const Frame& to) const {
  const Frame& a = c.anchor;
  // The anchor in W, then in F_a: F_a^-1 * F_b * A.
  const double gx = to.x + to.c * a.x - to.s * a.y, gy = to.y + to.s * a.x + to.c * a.y;
  const double dx = gx - from.x, dy = gy - from.y;
  const double rx = from.c * dx + from.s * dy - c.mean.x;
  const double ry = -from.s * dx + from.c * dy - c.mean.y;
  const double rt = wrap(to.theta + a.theta - from.theta - c.mean.theta);
  const double* w = c.info;
  const double m = w[0] * rx * rx + w[3] * ry * ry + w[5] * rt * rt +
                   2.0 * (w[1] * rx * ry + w[2] * rx * rt + w[4] * ry * rt);
  return 1.0 - std::exp(-0.5 * m);  // eq. (10), closure term
}

double SlamProblem::chain_cost(std::span<const std::uint32_t> choice, Frame* opened) const {
  static constexpr Frame kWorld{0.0, 0.0, 1.0, 0.0, 0.0};
  const Sample* samples = samples_.data();
  const std::size_t* offset = offset_.data();
  const std::uint32_t* pick = choice.data();
  const std::size_t layers = layer_count();
  double weight = 0.0;
  Frame frame = kWorld;  // F_1 = W
  std::size_t l = 0;
  for (const Event& e : events_) {
    // Layers up to fragment e.fragment: alignment terms of eq. (10) and the chain of eq. (8),
    // two samples at a time (their product does not wait for the frame: half the latency).
    for (; l + 1 < e.fragment; l += 2) {
      const Sample& s = samples[offset[l] + pick[l]];
      const Sample& t = samples[offset[l + 1] + pick[l + 1]];
      weight += s.unary + t.unary;
      frame = compose(frame, compose(s.pose, t.pose));
    }
    if (l < e.fragment) {
      const Sample& s = samples[offset[l] + pick[l]];
      weight += s.unary;
      frame = compose(frame, s.pose);
      ++l;
    }
    for (std::uint32_t k : e.opening) opened[closures_[k].slot] = frame;
    for (std::uint32_t k : e.closing) {
      const Closure& c = closures_[k];
      weight += closure_term(c, c.from_world ? kWorld : opened[c.slot], frame);
    }
  }
  for (; l < layers; ++l) weight += samples[offset[l] + pick[l]].unary;  // after the last closure
  return weight;
}

double SlamProblem::cost(std::span<const std::uint32_t> choice) const {
  // Frames F_a of closures with a > 0, kept until F_b is reached: on the stack unless many.
  constexpr std::size_t kOnStack = 16;
  if (kept_frames_ <= kOnStack) {
    Frame opened[kOnStack];
    return chain_cost(choice, opened);
  }
  std::vector<Frame> opened(kept_frames_);
  return chain_cost(choice, opened.data());
}

}  // namespace antslam::slam
