#include "slamgraph/slam_problem.hpp"

#include <algorithm>
#include <cmath>

namespace antslam::slam {

namespace {

using Frame = SlamProblem::Frame;

Frame to_frame(const Pose2& p) { return {p.x, p.y, std::cos(p.theta), std::sin(p.theta)}; }

/// a * b, eq. (8)'s product, without trigonometry.
Frame compose(const Frame& a, const Frame& b) {
  return {a.x + a.c * b.x - a.s * b.y, a.y + a.s * b.x + a.c * b.y, a.c * b.c - a.s * b.s,
          a.s * b.c + a.c * b.s};
}

/// CSR lists: for every fragment, the closures whose `key` is that fragment.
void bucket(std::size_t fragments, const std::vector<LoopClosure>& closures, bool by_from,
            std::vector<std::uint32_t>& begin, std::vector<std::uint32_t>& ids) {
  begin.assign(fragments + 1, 0);
  for (const LoopClosure& c : closures) ++begin[(by_from ? c.from : c.to) + 1];
  for (std::size_t i = 0; i < fragments; ++i) begin[i + 1] += begin[i];
  ids.assign(closures.size(), 0);
  std::vector<std::uint32_t> next(begin.begin(), begin.end() - 1);
  for (std::uint32_t k = 0; k < closures.size(); ++k) {
    const std::size_t key = by_from ? closures[k].from : closures[k].to;
    ids[next[key]++] = k;
  }
}

}  // namespace

SlamProblem::SlamProblem(const FragmentSet& set) {
  validate(set);
  const std::size_t n = set.fragments.size();
  offset_.assign(1, 0);
  for (std::size_t i = 1; i < n; ++i) {
    const Fragment& f = set.fragments[i];
    for (const Pose2& s : f.samples) samples_.push_back({to_frame(s), 1.0 - f.alignment->value(s)});
    offset_.push_back(samples_.size());
  }
  for (const LoopClosure& c : set.closures) {
    Closure k{};
    k.from_world = c.from == 0;
    k.slot = static_cast<std::uint32_t>(k.from_world ? 0 : kept_frames_++);
    k.anchor = to_frame(c.anchor);
    k.mean = to_frame(c.hypothesis.mean());
    const Eigen::Matrix3d& w = c.hypothesis.information();
    const double info[6] = {w(0, 0), w(0, 1), w(0, 2), w(1, 1), w(1, 2), w(2, 2)};
    std::copy(std::begin(info), std::end(info), std::begin(k.info));
    closures_.push_back(k);
  }
  bucket(n, set.closures, true, open_begin_, open_ids_);
  bucket(n, set.closures, false, close_begin_, close_ids_);
  has_event_.assign(n, 0);
  for (const LoopClosure& c : set.closures) has_event_[c.from] = has_event_[c.to] = 1;
}

double SlamProblem::closure_term(const Closure& c, const Frame& from, const Frame& to) const {
  const Frame g = compose(to, c.anchor);  // the anchor in W
  // Pose of the anchor in F_a: F_a^-1 * g.
  const double dx = g.x - from.x, dy = g.y - from.y;
  const double px = from.c * dx + from.s * dy, py = -from.s * dx + from.c * dy;
  const double pc = from.c * g.c + from.s * g.s, ps = from.c * g.s - from.s * g.c;
  // Residual to H; its angle from the rotation R_H^T R_p, already wrapped.
  const double rx = px - c.mean.x, ry = py - c.mean.y;
  const double rt = std::atan2(c.mean.c * ps - c.mean.s * pc, c.mean.c * pc + c.mean.s * ps);
  const double* w = c.info;
  const double m = w[0] * rx * rx + w[3] * ry * ry + w[5] * rt * rt +
                   2.0 * (w[1] * rx * ry + w[2] * rx * rt + w[4] * ry * rt);
  return 1.0 - std::exp(-0.5 * m);
}

double SlamProblem::chain_cost(std::span<const std::uint32_t> choice, Frame* opened) const {
  static constexpr Frame kWorld{0.0, 0.0, 1.0, 0.0};
  double weight = 0.0;
  Frame frame = kWorld;  // F_1 = W
  const std::size_t layers = layer_count();
  for (std::size_t l = 0; l < layers; ++l) {
    const Sample& s = samples_[offset_[l] + choice[l]];
    weight += s.unary;               // eq. (10), alignment term of fragment l + 2
    frame = compose(frame, s.pose);  // eq. (8)
    const std::size_t i = l + 1;
    if (!has_event_[i]) continue;
    for (std::uint32_t k = open_begin_[i]; k < open_begin_[i + 1]; ++k)
      opened[closures_[open_ids_[k]].slot] = frame;
    for (std::uint32_t k = close_begin_[i]; k < close_begin_[i + 1]; ++k) {
      const Closure& c = closures_[close_ids_[k]];
      weight += closure_term(c, c.from_world ? kWorld : opened[c.slot], frame);
    }
  }
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
