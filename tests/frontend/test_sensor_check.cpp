// The reader's checks of a log against its geometry: no-return spikes, readings above a declared
// maximum range, beams against the field of view at a declared resolution.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "antslam/frontend/laser_log.hpp"
#include "antslam/frontend/sensor_check.hpp"
#include "antslam/frontend/simulator.hpp"

namespace antslam::frontend {
namespace {

constexpr double kPi = std::numbers::pi;

/// A simulated drive through the ring corridor, ranges rounded to centimetres as CARMEN logs
/// hold them; every `spike_every`-th reading (0: none) replaced by `spike`.
LaserLog corridor_log(std::size_t spike_every, float spike) {
  SimulationSettings sim;
  sim.beams = 181;
  sim.step = 0.5;
  const std::vector<Eigen::Vector2d> path{{0, 0}, {20, 0}, {20, 14}};
  LaserLog log = simulate_run(loop_world(), path, sim, 3).log;
  std::size_t n = 0;
  for (LaserScan& scan : log.scans) {
    scan.max_range = 80.0;
    for (float& r : scan.ranges) {
      r = std::round(r * 100.0F) / 100.0F;
      if (spike_every > 0 && ++n % spike_every == 0) r = spike;
    }
  }
  return log;
}

TEST(SensorCheck, AFixedNoReturnValueBelowTheMaximumIsFoundAndRemoved) {
  LaserLog log = corridor_log(13, 51.14F);  // 7.7 % of the readings, at every beam in turn
  const std::vector<NoReturnSpike> spikes = find_no_return_spikes(log);
  ASSERT_EQ(spikes.size(), 1U);
  EXPECT_FLOAT_EQ(spikes[0].value, 51.14F);
  EXPECT_NEAR(spikes[0].share, 1.0 / 13.0, 0.01);
  check_sensor(log);
  ASSERT_EQ(log.warnings.size(), 1U);
  EXPECT_NE(log.warnings[0].find("exactly 51.140 m"), std::string::npos) << log.warnings[0];
  for (const LaserScan& scan : log.scans)
    for (const float r : scan.ranges) EXPECT_NE(r, 51.14F);
}

TEST(SensorCheck, OrdinaryRangesAreNotSpikes) {
  // Centimetre ranges repeat often (walls at the same distance), but always with neighbours.
  LaserLog log = corridor_log(0, 0.0F);
  EXPECT_TRUE(find_no_return_spikes(log).empty());
  // A robot standing still: every beam repeats its reading, each at one beam index only.
  LaserLog still = corridor_log(0, 0.0F);
  still.scans.assign(400, still.scans.front());
  EXPECT_TRUE(find_no_return_spikes(still).empty());
  check_sensor(still);
  EXPECT_TRUE(still.warnings.empty());
}

std::string flaser_line(int n, double range) {
  std::ostringstream line;
  line << "FLASER " << n;
  for (int k = 0; k < n; ++k) line << ' ' << range;
  line << " 1 2 0.5 1 2 0.5 10.5 host 10.6\n";
  return line.str();
}

TEST(SensorCheck, ReadingsAboveADeclaredMaximumAreReported) {
  const std::string scans = flaser_line(5, 81.91) + flaser_line(5, 3.0);
  const LaserLog declared = parse_carmen("PARAM robot_front_laser_max 50\n" + scans, "mem");
  ASSERT_EQ(declared.warnings.size(), 1U);
  EXPECT_NE(declared.warnings[0].find("5 readings (50.0 %) lie above the declared maximum range "
                                      "50.00 m (up to 81.91 m)"),
            std::string::npos)
      << declared.warnings[0];
  // Without a declared maximum the default (80 m) is only an assumption: no warning.
  EXPECT_TRUE(parse_carmen(scans, "mem").warnings.empty());
  SensorOverrides o;
  o.max_range = 60.0;
  EXPECT_EQ(parse_carmen(scans, "mem", o).warnings.size(), 1U);
}

TEST(SensorCheck, ADeclaredResolutionSetsTheFieldOfViewOrIsCheckedAgainstIt) {
  // 360 beams at 0.5 deg span 179.5 deg.
  const LaserLog log =
      parse_carmen("PARAM laser_front_laser_resolution 0.5\n" + flaser_line(360, 2.0), "mem");
  EXPECT_NEAR(log.scans[0].angle_step, 0.5 * kPi / 180.0, 1e-12);
  EXPECT_NEAR(log.scans[0].first_angle, -0.5 * 179.5 * kPi / 180.0, 1e-12);
  EXPECT_TRUE(log.warnings.empty());
  const LaserLog both =
      parse_carmen("PARAM laser_front_laser_resolution 0.5\nPARAM laser_front_laser_fov 180\n" +
                       flaser_line(360, 2.0),
                   "mem");
  ASSERT_EQ(both.warnings.size(), 1U);
  EXPECT_NE(both.warnings[0].find("360 beams at the declared 0.500 deg per beam span 179.50 deg, "
                                  "not the field of view 180.00 deg"),
            std::string::npos)
      << both.warnings[0];
  // 361 beams fit 180 deg at 0.5 deg.
  EXPECT_TRUE(parse_carmen("PARAM laser_front_laser_resolution 0.5\nPARAM laser_front_laser_fov "
                           "180\n" +
                               flaser_line(361, 2.0),
                           "mem")
                  .warnings.empty());
  EXPECT_THROW(parse_carmen("PARAM laser_front_laser_resolution -1\n" + flaser_line(3, 1.0), "m"),
               std::runtime_error);
}

}  // namespace
}  // namespace antslam::frontend
