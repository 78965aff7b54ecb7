#pragma once
// Occupancy-grid maps of a set of fragments placed at any world poses (paper Figs. 4 and 5):
// the scan-matcher map (fragments at the frames the scan matcher gave them, every second
// fragment tinted as in Fig. 4), an optimized map (fragments at the optimizer's frames, e.g.
// slam::world_frames of the best sample sequence), and the average over many trials (Fig. 5b).
// Each beam clears the cells it crosses and marks the cell it ends in (log-odds).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "antslam/frontend/frontend.hpp"
#include "antslam/frontend/image.hpp"
#include "antslam/frontend/laser_log.hpp"
#include "antslam/slamgraph/pose2.hpp"

namespace antslam::frontend {

struct MapRenderSettings {
  double resolution = 0.05;           ///< metres per pixel (paper: 4 cm)
  double max_range = 20.0;            ///< metres; longer readings and no-returns are not drawn
  double margin = 1.0;                ///< metres of border around the map
  bool tint_alternate = true;         ///< every second fragment's walls in red (Fig. 4)
  bool draw_frames = true;            ///< draw each fragment frame F_i (= E_{i-1}) as axes
  std::size_t max_pixels = 50000000;  ///< pixels at most (count): render_map refuses larger maps,
                                      ///< fitting_resolution coarsens the cell to fit
};

/// Throws std::invalid_argument naming the first nonsensical field.
void validate(const MapRenderSettings& settings);

/// What a map is made of: per fragment, its scans (index into the log) and the robot pose of
/// each in the fragment's frame.
struct MapScan {
  std::size_t scan = 0;  ///< index into LaserLog::scans
  slam::Pose2 robot;     ///< robot pose in the fragment's frame
};
using MapLayout = std::vector<std::vector<MapScan>>;

/// The finest cell size, not finer than settings.resolution and in whole millimetres when
/// coarsened, at which the map of every placement in `trials` fits settings.max_pixels (a large
/// outdoor log drawn at 5 cm would not). Throws std::invalid_argument like render_map for
/// wrong sizes or non-finite frames.
double fitting_resolution(const LaserLog& log, const MapLayout& layout,
                          std::span<const std::vector<slam::Pose2>> trials,
                          const MapRenderSettings& settings);

/// The layout of a frontend run: every scan in the fragment it belongs to.
MapLayout map_layout(const FrontendResult& result);

/// The scan-matcher world frames F_i of a frontend run (paper Fig. 5a).
std::vector<slam::Pose2> scan_matcher_frames(const FrontendResult& result);

/// The map with fragment i at world pose frames[i] (frames.size() == layout.size()).
/// Occupied cells black (red for odd fragments if tinting), free white, unknown grey.
Image render_map(const LaserLog& log, const MapLayout& layout, std::span<const slam::Pose2> frames,
                 const MapRenderSettings& settings);

/// The average of the occupancy probabilities of many trials' maps (Fig. 5b): each trial is one
/// set of fragment world poses; darker = occupied in more trials.
Image render_average_map(const LaserLog& log, const MapLayout& layout,
                         std::span<const std::vector<slam::Pose2>> trials,
                         const MapRenderSettings& settings);

/// The average map over `count` random sample sequences of a frontend run (one sample of
/// eq. (7) per fragment, placed by eq. (8)), drawn like Fig. 5b: the spread of maps the
/// optimizer chooses from. The sequences are drawn from one stream seeded by `seed`.
Image render_sample_average_map(const LaserLog& log, const FrontendResult& result,
                                std::size_t count, std::uint64_t seed,
                                const MapRenderSettings& settings);

}  // namespace antslam::frontend
