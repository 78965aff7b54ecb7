#pragma once
// A tinySLAM-style single-hypothesis mapper, the baseline of the second paper (Sec. II-A;
// Steux and El Hamzaoui, "tinySLAM: a SLAM algorithm in less than 200 lines of C-language
// program", 2010): predict the pose with the odometry, refine it with a Monte-Carlo search that
// adds normally distributed perturbations to each pose component and keeps the pose whose scan
// points lie on the most occupied cells, then write the scan into the one map with eq. (1)
// (occupancy_grid.hpp). Following the improved tinySLAM (Huletski et al. 2015, the paper's ref.
// [15]) a scan whose pose the matcher moved is written with a lower quality.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "antslam/aco/random.hpp"
#include "antslam/baselines/occupancy_grid.hpp"
#include "antslam/frontend/image.hpp"
#include "antslam/frontend/laser_log.hpp"
#include "antslam/slamgraph/pose2.hpp"
#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::baselines {

/// The most draws without improvement a search may make (a search of more never ends in time).
inline constexpr std::size_t kMaxStop = 1'000'000;

struct TinySlamSettings {
  double resolution = 0.025;           ///< metres per map cell (tinySLAM: 1 cm)
  double min_range = 0.1;              ///< metres; shorter readings are dropped
  double max_range = 20.0;             ///< metres; longer readings and no-returns are dropped
  double hole_width = 0.6;             ///< metres; obstacles are blurred over this width (tinySLAM)
  double quality = 0.2;                ///< q of eq. (1) for a scan at the predicted pose (50/256)
  double refined_quality = 0.1;        ///< q of eq. (1) for a scan whose pose the search moved
  double sigma_xy = 0.1;               ///< metres, std of the perturbations of x and y
  double sigma_theta = 0.1;            ///< radians, std of the perturbation of the heading
  std::size_t stop = 1000;             ///< draws without improvement that end the search (count)
  std::size_t min_points = 10;         ///< fewer usable readings: keep the predicted pose
  std::uint64_t seed = 1;              ///< seeds the Monte-Carlo search
  std::size_t max_cells = 50'000'000;  ///< map size limit (cells)
};

/// Throws std::invalid_argument naming the first nonsensical field.
void validate(const TinySlamSettings& settings);

/// The end points of a scan's usable readings in the robot frame (laser pose applied).
std::vector<Eigen::Vector2d> scan_points(const frontend::LaserScan& scan,
                                         const TinySlamSettings& settings);

/// The mean occupancy of the cells the points fall in when the robot is at `pose`: the
/// correspondence of scan and map (tinySLAM's distance, with occupancy instead of 1 - it).
double correspondence(const OccupancyGrid& map, std::span<const Eigen::Vector2d> points,
                      const slam::Pose2& pose);

struct SearchResult {
  slam::Pose2 pose;             ///< the best pose found
  double score = 0.0;           ///< its correspondence
  std::size_t evaluations = 0;  ///< correspondences computed (count)
};

/// tinySLAM's Monte-Carlo search (ts_monte_carlo_search): draws around the current centre
/// (start) with the given spreads; each draw that scores better becomes the best; after more
/// than stop / 3 draws without improvement the best becomes the centre and both spreads are
/// halved (if it improved since the last halving); stops after `stop` draws without improvement.
SearchResult monte_carlo_search(const OccupancyGrid& map, std::span<const Eigen::Vector2d> points,
                                const slam::Pose2& start, const TinySlamSettings& settings,
                                aco::Rng& rng);

class TinySlam {
 public:
  explicit TinySlam(const TinySlamSettings& settings);

  /// Processes the next scan: predicts its pose from the odometry increment, refines it,
  /// writes it into the map. Returns the robot pose (the first scan's is its odometry).
  slam::Pose2 add_scan(const frontend::LaserScan& scan);

  const OccupancyGrid& map() const { return map_; }
  std::size_t evaluations() const { return evaluations_; }
  std::size_t unmatched() const { return unmatched_; }

 private:
  void insert(std::span<const Eigen::Vector2d> points, const slam::Pose2& pose, double quality);

  TinySlamSettings settings_;
  OccupancyGrid map_;
  aco::Rng rng_;
  bool started_ = false;
  slam::Pose2 pose_;
  slam::Pose2 odometry_;
  std::size_t evaluations_ = 0;
  std::size_t unmatched_ = 0;
};

struct TinySlamResult {
  slam::Trajectory trajectory;  ///< robot pose of every scan, with the scan's timestamp
  OccupancyGrid map;            ///< the final map
  std::size_t evaluations = 0;  ///< correspondences computed (count)
  std::size_t unmatched = 0;    ///< scans kept at the prediction (too few readings)
};

/// Runs the mapper over a whole log; `progress(done)` is called after each scan if given.
TinySlamResult run_tinyslam(const frontend::LaserLog& log, const TinySlamSettings& settings,
                            const std::function<void(std::size_t)>& progress = {});

/// The map as an image: grey level 255 (1 - occupancy), north up, one pixel per cell, cropped
/// to the cells written.
frontend::Image map_image(const OccupancyGrid& map);

}  // namespace antslam::baselines
