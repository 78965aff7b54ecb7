// CARMEN laser logs (frontend/laser_log.hpp): any input is a log or one line naming the problem;
// every scan's geometry is within the limits the reader promises, and the writer's output of
// a log reads back with the same scans.

#include <cmath>
#include <exception>
#include <sstream>

#include "antslam/frontend/carmen_writer.hpp"
#include "antslam/frontend/laser_log.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antslam;
  frontend::LaserLog log;
  if (!fuzz::reads([&] {
        log = frontend::parse_carmen(fuzz::text_of(data, size), std::string(fuzz::kSource));
      }))
    return 0;
  for (const frontend::LaserScan& s : log.scans) {
    fuzz::require(s.max_range > 0.0 && s.max_range <= frontend::kMaxLaserRange, "max range");
    fuzz::require(std::hypot(s.laser_pose.x, s.laser_pose.y) <= frontend::kMaxLaserOffset,
                  "laser offset");
    fuzz::require(std::isfinite(s.first_angle) && std::isfinite(s.angle_step), "beam angles");
    fuzz::require(std::abs(s.odometry.x) <= slam::kMaxCoordinate &&
                      std::abs(s.odometry.y) <= slam::kMaxCoordinate,
                  "odometry within the coordinate limit");
  }
  std::ostringstream written;
  try {
    frontend::write_carmen(written, log);
  } catch (const std::exception& e) {
    fuzz::finding("the writer refuses what the reader gave", e.what());
  }
  frontend::LaserLog back;
  fuzz::require(fuzz::reads([&] { back = frontend::parse_carmen(written.str(), "fuzz-written"); }),
                "the writer's output reads back");
  fuzz::require(back.scans.size() == log.scans.size(), "the same scans after a round trip");
  return 0;
}
