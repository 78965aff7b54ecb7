#include "antslam/frontend/sensor_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <unordered_map>

namespace antslam::frontend {

namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c, d);
  return buffer;
}

bool is_return(float r, const LaserScan& scan) {
  return r > 0.0F && static_cast<double>(r) < scan.max_range;
}

}  // namespace

std::vector<NoReturnSpike> find_no_return_spikes(const LaserLog& log, const SpikeSettings& s) {
  std::unordered_map<float, std::size_t> counts;
  std::size_t total = 0;
  for (const LaserScan& scan : log.scans)
    for (const float r : scan.ranges)
      if (is_return(r, scan)) {
        ++counts[r];
        ++total;
      }
  // Candidates: the most frequent values with enough readings.
  std::vector<NoReturnSpike> candidates;
  for (const auto& [value, n] : counts)
    if (n >= s.min_readings && static_cast<double>(n) >= s.min_share * static_cast<double>(total))
      candidates.push_back({value, n, static_cast<double>(n) / static_cast<double>(total)});
  std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) {
    return a.readings != b.readings ? a.readings > b.readings : a.value < b.value;
  });
  std::vector<NoReturnSpike> spikes;
  for (const NoReturnSpike& c : candidates) {
    if (spikes.size() == s.max_spikes) break;
    // Isolated: fewer readings near the value than at it; spread over many beam indices.
    std::size_t near = 0;
    for (const auto& [value, n] : counts)
      if (value != c.value && std::abs(value - c.value) <= s.neighbourhood) near += n;
    // No-return codes sit at the far end: above most of the other returns.
    std::size_t below = 0;
    for (const auto& [value, n] : counts) below += value < c.value ? n : 0;
    if (near >= c.readings ||
        static_cast<double>(below) < s.min_rank * static_cast<double>(total - c.readings))
      continue;
    if (total == c.readings) continue;
    std::size_t beams = 0, indices = 0;
    std::vector<bool> seen;
    for (const LaserScan& scan : log.scans) {
      if (scan.ranges.size() > seen.size()) seen.resize(scan.ranges.size(), false);
      for (std::size_t k = 0; k < scan.ranges.size(); ++k)
        if (scan.ranges[k] == c.value && !seen[k]) {
          seen[k] = true;
          ++beams;
        }
    }
    indices = seen.size();
    if (static_cast<double>(beams) >= s.min_beam_share * static_cast<double>(indices))
      spikes.push_back(c);
  }
  return spikes;
}

void check_sensor(LaserLog& log, const SpikeSettings& settings) {
  for (const NoReturnSpike& spike : find_no_return_spikes(log, settings)) {
    for (LaserScan& scan : log.scans)
      for (float& r : scan.ranges)
        if (r == spike.value) r = static_cast<float>(scan.max_range);
    log.warnings.push_back(format(
        "%.0f readings (%.1f %% of the returns) are exactly %.3f m, at many beams and with fewer "
        "readings within %.1f m of it: taken as the laser's no-return value",
        static_cast<double>(spike.readings), 100.0 * spike.share, static_cast<double>(spike.value),
        settings.neighbourhood));
  }
  const SensorGeometry& g = log.flaser_geometry;
  std::size_t above = 0, readings = 0;
  double highest = 0.0;
  for (const LaserScan& scan : log.scans)
    for (const float r : scan.ranges) {
      ++readings;
      if (static_cast<double>(r) > scan.max_range) {
        ++above;
        highest = std::max(highest, static_cast<double>(r));
      }
    }
  if (g.max_range_declared && above > 0)
    log.warnings.push_back(format(
        "%.0f readings (%.1f %%) lie above the declared maximum range %.2f m (up to %.2f m): "
        "taken as no-returns (check --max-range)",
        static_cast<double>(above),
        100.0 * static_cast<double>(above) / static_cast<double>(readings), g.max_range, highest));
  if (g.angle_step && g.field_of_view_declared)
    for (const LaserScan& scan : log.scans) {
      const double span = *g.angle_step * static_cast<double>(scan.ranges.size() - 1);
      if (std::abs(span - g.field_of_view) > 0.5 * *g.angle_step) {
        log.warnings.push_back(format(
            "%.0f beams at the declared %.3f deg per beam span %.2f deg, not the field of view "
            "%.2f deg (check --fov)",
            static_cast<double>(scan.ranges.size()), *g.angle_step * kDegrees, span * kDegrees,
            g.field_of_view * kDegrees));
        break;
      }
    }
}

}  // namespace antslam::frontend
