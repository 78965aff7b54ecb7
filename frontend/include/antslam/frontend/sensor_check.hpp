#pragma once
// Checks of a laser log against its declared geometry, run by the reader so that every command
// sees the same scans:
//   - no-return spikes: some lasers report "no return" as a fixed value below the declared
//     maximum (e.g. 50 m in a log whose maximum is 80 m). Such a value holds a large share of
//     all readings, at many beam indices, fewer readings lie near it than at it, and it lies
//     above most other returns; those readings are turned into no-returns (the scan's max
//     range) and the log says so;
//   - readings above a declared maximum range (they are no-returns; the maximum may be wrong);
//   - a beam count that does not fit the field of view at the declared angular resolution.
// Each finding is one line in LaserLog::warnings.

#include <cstddef>
#include <vector>

#include "antslam/frontend/laser_log.hpp"

namespace antslam::frontend {

struct SpikeSettings {
  double min_share = 0.002;        ///< share of all readings at one exact value, at least
  std::size_t min_readings = 100;  ///< readings at the value, at least (count)
  double min_beam_share = 0.1;     ///< share of the beam indices the value occurs at, at least
  double neighbourhood = 0.5;      ///< metres: readings this close to the value (at other
                                   ///< values) must be fewer than the spike's own
  double min_rank = 0.9;       ///< share of the other returns that lie below the value, at least
                               ///< (no-return codes sit at the far end)
  std::size_t max_spikes = 3;  ///< distinct no-return values looked for, at most (count)
};

/// One value that stands for "no return".
struct NoReturnSpike {
  float value = 0.0F;        ///< metres, the exact reading
  std::size_t readings = 0;  ///< readings at it (count)
  double share = 0.0;        ///< of all readings in (0, max range)
};

/// The no-return spikes of the log's scans (readings in (0, the scan's max range) only), most
/// frequent first.
std::vector<NoReturnSpike> find_no_return_spikes(const LaserLog& log,
                                                 const SpikeSettings& settings = {});

/// Marks the readings of every spike as no-returns (the scan's max range) and adds a warning
/// per spike, a warning for readings above a declared maximum range, and one for a beam count
/// that does not fit the field of view at a declared angular resolution (FLASER scans).
void check_sensor(LaserLog& log, const SpikeSettings& settings = {});

}  // namespace antslam::frontend
