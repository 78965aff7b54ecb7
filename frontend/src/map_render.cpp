#include "antslam/frontend/map_render.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "antslam/aco/random.hpp"

namespace antslam::frontend {

namespace {

constexpr float kFree = -0.4F;     // log-odds of a cell a beam crosses
constexpr float kOccupied = 0.9F;  // log-odds of the cell a beam ends in
constexpr float kClamp = 20.0F;    // log-odds saturate here
constexpr Rgb kUnknown{205, 205, 205};

/// The pose of the laser of scan `s` when its fragment sits at `frame`.
slam::Pose2 laser_in_world(const LaserScan& scan, const slam::Pose2& frame, const MapScan& s) {
  return frame * s.robot * scan.laser_pose;
}

/// Calls f(laser_cell_world, end_point_world) for every drawable beam.
template <typename F>
void for_each_beam(const LaserLog& log, const MapLayout& layout,
                   std::span<const slam::Pose2> frames, double max_range, F&& f) {
  for (std::size_t i = 0; i < layout.size(); ++i)
    for (const MapScan& s : layout[i]) {
      const LaserScan& scan = log.scans.at(s.scan);
      const slam::Pose2 laser = laser_in_world(scan, frames[i], s);
      const double limit = std::min(max_range, scan.max_range);
      for (std::size_t k = 0; k < scan.ranges.size(); ++k) {
        const double r = scan.ranges[k];
        if (!(r > 0.0 && r < limit)) continue;
        const double a = scan.beam_angle(k);
        f(i, laser, laser * Eigen::Vector2d(r * std::cos(a), r * std::sin(a)));
      }
    }
}

struct Frame {
  double res = 0.05, x0 = 0.0, y0 = 0.0;  // (x0, y0): lower-left corner of cell (0, 0)
  std::size_t width = 0, height = 0;
  long cell_x(double x) const { return static_cast<long>(std::floor((x - x0) / res)); }
  long cell_y(double y) const { return static_cast<long>(std::floor((y - y0) / res)); }
};

/// The world box (metres) that the beams, lasers and frames of all trials cover.
struct Extent {
  double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
  void extend(const Eigen::Vector2d& p) {
    lo_x = std::min(lo_x, p.x());
    lo_y = std::min(lo_y, p.y());
    hi_x = std::max(hi_x, p.x());
    hi_y = std::max(hi_y, p.y());
  }
};

Extent extent_of(const LaserLog& log, const MapLayout& layout,
                 std::span<const std::vector<slam::Pose2>> trials, const MapRenderSettings& s) {
  Extent e;
  for (const std::vector<slam::Pose2>& frames : trials) {
    if (frames.size() != layout.size())
      throw std::invalid_argument("map: " + std::to_string(frames.size()) + " frames for " +
                                  std::to_string(layout.size()) + " fragments");
    for (const slam::Pose2& f : frames)
      if (!std::isfinite(f.x) || !std::isfinite(f.y) || !std::isfinite(f.theta))
        throw std::invalid_argument("map: a fragment pose is not finite");
    for_each_beam(log, layout, frames, s.max_range,
                  [&](std::size_t, const slam::Pose2& laser, const Eigen::Vector2d& end) {
                    e.extend(laser.translation());
                    e.extend(end);
                  });
    for (const slam::Pose2& f : frames) e.extend(f.translation());
  }
  if (!(e.lo_x <= e.hi_x)) throw std::invalid_argument("map: nothing to draw");
  return e;
}

/// Pixels of a map of the extent at a resolution (as doubles: no overflow).
double pixels(const Extent& e, double margin, double resolution) {
  return std::ceil((e.hi_x - e.lo_x + 2.0 * margin) / resolution) *
         std::ceil((e.hi_y - e.lo_y + 2.0 * margin) / resolution);
}

Frame frame_for(const LaserLog& log, const MapLayout& layout,
                std::span<const std::vector<slam::Pose2>> trials, const MapRenderSettings& s) {
  const Extent e = extent_of(log, layout, trials, s);
  Frame g;
  g.res = s.resolution;
  g.x0 = e.lo_x - s.margin;
  g.y0 = e.lo_y - s.margin;
  const double w = std::ceil((e.hi_x + s.margin - g.x0) / s.resolution);
  const double h = std::ceil((e.hi_y + s.margin - g.y0) / s.resolution);
  if (w * h > static_cast<double>(s.max_pixels))
    throw std::invalid_argument("map: " + std::to_string(static_cast<long>(w)) + " x " +
                                std::to_string(static_cast<long>(h)) +
                                " pixels is more than max_pixels");
  g.width = static_cast<std::size_t>(w);
  g.height = static_cast<std::size_t>(h);
  return g;
}

/// Log-odds occupancy, with which fragments' beams ended in each cell.
class Occupancy {
 public:
  explicit Occupancy(const Frame& f)
      : f_(f),
        logodds_(f.width * f.height, 0.0F),
        odd_(f.width * f.height, 0),
        even_(f.width * f.height, 0) {}

  void beam(std::size_t fragment, const slam::Pose2& laser, const Eigen::Vector2d& end) {
    // Bresenham from the laser's cell to the end cell: crossed cells are free.
    long x = f_.cell_x(laser.x), y = f_.cell_y(laser.y);
    const long x1 = f_.cell_x(end.x()), y1 = f_.cell_y(end.y());
    const long dx = std::abs(x1 - x), dy = -std::abs(y1 - y);
    const long sx = x < x1 ? 1 : -1, sy = y < y1 ? 1 : -1;
    long err = dx + dy;
    while (x != x1 || y != y1) {
      add(x, y, kFree);
      const long e2 = 2 * err;
      if (e2 >= dy) {
        err += dy;
        x += sx;
      }
      if (e2 <= dx) {
        err += dx;
        y += sy;
      }
    }
    std::size_t i = 0;
    if (inside(x1, y1, i)) {
      logodds_[i] = std::clamp(logodds_[i] + kOccupied, -kClamp, kClamp);
      ++(fragment % 2 == 1 ? odd_ : even_)[i];
    }
  }

  float logodds(std::size_t i) const { return logodds_[i]; }
  bool odd_dominates(std::size_t i) const { return odd_[i] > even_[i]; }

 private:
  bool inside(long x, long y, std::size_t& i) const {
    if (x < 0 || y < 0 || static_cast<std::size_t>(x) >= f_.width ||
        static_cast<std::size_t>(y) >= f_.height)
      return false;
    i = static_cast<std::size_t>(y) * f_.width + static_cast<std::size_t>(x);
    return true;
  }
  void add(long x, long y, float v) {
    std::size_t i = 0;
    if (inside(x, y, i)) logodds_[i] = std::clamp(logodds_[i] + v, -kClamp, kClamp);
  }

  Frame f_;
  std::vector<float> logodds_;
  std::vector<std::uint32_t> odd_, even_;
};

Occupancy occupancy(const LaserLog& log, const MapLayout& layout,
                    std::span<const slam::Pose2> frames, const Frame& f, double max_range) {
  Occupancy grid(f);
  for_each_beam(log, layout, frames, max_range,
                [&](std::size_t i, const slam::Pose2& laser, const Eigen::Vector2d& end) {
                  grid.beam(i, laser, end);
                });
  return grid;
}

void draw_line(Image& image, const Frame& f, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
               Rgb colour) {
  const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / (0.5 * f.res))));
  for (int k = 0; k <= steps; ++k) {
    const Eigen::Vector2d p = a + (b - a) * (static_cast<double>(k) / steps);
    image.plot(f.cell_x(p.x()), static_cast<long>(f.height) - 1 - f.cell_y(p.y()), colour);
  }
}

void draw_frames(Image& image, const Frame& f, std::span<const slam::Pose2> frames) {
  const double length = std::max(0.5, 10.0 * f.res);
  for (const slam::Pose2& p : frames) {
    draw_line(image, f, p.translation(), p * Eigen::Vector2d(length, 0.0), Rgb{0, 90, 255});
    draw_line(image, f, p.translation(), p * Eigen::Vector2d(0.0, length), Rgb{0, 170, 0});
  }
}

}  // namespace

void validate(const MapRenderSettings& s) {
  if (!(s.resolution > 0.0) || !std::isfinite(s.resolution))
    throw std::invalid_argument("map: resolution must be a positive number of metres");
  if (!(s.max_range > 0.0) || !std::isfinite(s.max_range))
    throw std::invalid_argument("map: max_range must be a positive number of metres");
  if (!(s.margin >= 0.0) || !std::isfinite(s.margin))
    throw std::invalid_argument("map: margin must be >= 0");
  if (s.max_pixels < 10000) throw std::invalid_argument("map: max_pixels must be at least 10000");
}

double fitting_resolution(const LaserLog& log, const MapLayout& layout,
                          std::span<const std::vector<slam::Pose2>> trials,
                          const MapRenderSettings& settings) {
  validate(settings);
  const Extent e = extent_of(log, layout, trials, settings);
  const auto cap = static_cast<double>(settings.max_pixels);
  if (pixels(e, settings.margin, settings.resolution) <= cap) return settings.resolution;
  // The area's square root per pixel is a lower bound; whole cells need a little more.
  double resolution = std::sqrt((e.hi_x - e.lo_x + 2.0 * settings.margin) *
                                (e.hi_y - e.lo_y + 2.0 * settings.margin) / cap);
  resolution = std::ceil(resolution * 1000.0) / 1000.0;  // whole millimetres
  while (pixels(e, settings.margin, resolution) > cap)
    resolution = std::ceil(resolution * 1010.0) / 1000.0;
  return resolution;
}

MapLayout map_layout(const FrontendResult& result) {
  MapLayout layout;
  for (const FragmentRecord& f : result.fragments) {
    std::vector<MapScan> scans;
    for (std::size_t k = 0; k < f.scan_count; ++k)
      scans.push_back({f.first_scan + k, f.trajectory[k].pose});
    layout.push_back(std::move(scans));
  }
  return layout;
}

std::vector<slam::Pose2> scan_matcher_frames(const FrontendResult& result) {
  std::vector<slam::Pose2> frames;
  for (const FragmentRecord& f : result.fragments) frames.push_back(f.frame);
  return frames;
}

Image render_map(const LaserLog& log, const MapLayout& layout, std::span<const slam::Pose2> frames,
                 const MapRenderSettings& settings) {
  validate(settings);
  const std::vector<slam::Pose2> trial(frames.begin(), frames.end());
  const Frame f = frame_for(log, layout, std::span(&trial, 1), settings);
  const Occupancy grid = occupancy(log, layout, frames, f, settings.max_range);
  Image image(f.width, f.height, kUnknown);
  for (std::size_t y = 0; y < f.height; ++y)
    for (std::size_t x = 0; x < f.width; ++x) {
      const std::size_t i = y * f.width + x;
      const float l = grid.logodds(i);
      Rgb& pixel = image.at(x, f.height - 1 - y);
      if (l > 0.5F)
        pixel = settings.tint_alternate && grid.odd_dominates(i) ? Rgb{210, 0, 0} : Rgb{0, 0, 0};
      else if (l < -0.2F)
        pixel = Rgb{255, 255, 255};
    }
  if (settings.draw_frames) draw_frames(image, f, frames);
  return image;
}

Image render_average_map(const LaserLog& log, const MapLayout& layout,
                         std::span<const std::vector<slam::Pose2>> trials,
                         const MapRenderSettings& settings) {
  validate(settings);
  if (trials.empty()) throw std::invalid_argument("map: no trials to average");
  const Frame f = frame_for(log, layout, trials, settings);
  std::vector<double> mean(f.width * f.height, 0.0);
  for (const std::vector<slam::Pose2>& frames : trials) {
    const Occupancy grid = occupancy(log, layout, frames, f, settings.max_range);
    for (std::size_t i = 0; i < mean.size(); ++i)
      mean[i] += 1.0 / (1.0 + std::exp(-static_cast<double>(grid.logodds(i))));
  }
  Image image(f.width, f.height);
  for (std::size_t y = 0; y < f.height; ++y)
    for (std::size_t x = 0; x < f.width; ++x) {
      const double p = mean[y * f.width + x] / static_cast<double>(trials.size());
      const auto grey = static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - p)));
      image.at(x, f.height - 1 - y) = Rgb{grey, grey, grey};
    }
  return image;
}

Image render_sample_average_map(const LaserLog& log, const FrontendResult& result,
                                std::size_t count, std::uint64_t seed,
                                const MapRenderSettings& settings) {
  const slam::FragmentSet& set = result.fragment_set;
  const std::size_t samples = set.fragments.size() > 1 ? set.fragments[1].samples.size() : 0;
  std::vector<std::vector<slam::Pose2>> trials;
  aco::Rng rng(aco::mix_seed(seed, 0xA7E5));
  for (std::size_t t = 0; t < count; ++t) {
    std::vector<std::uint32_t> choice(set.layer_count());
    for (std::uint32_t& c : choice) c = rng.below(static_cast<std::uint32_t>(samples));
    trials.push_back(slam::world_frames(set, choice));
  }
  return render_average_map(log, map_layout(result), trials, settings);
}

}  // namespace antslam::frontend
