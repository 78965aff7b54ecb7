#pragma once
// Relative pose error (Sturm et al. 2012): the drift of the estimate over a fixed step. For
// associated pairs (e_i, r_i) in reference order and every i with a partner j = step(i),
//   E_i = (r_i^-1 r_j)^-1 (e_i^-1 e_j)          (see relative_error.hpp)
// with step(i) = i + frames, or the first j whose distance travelled along the reference path
// r_i -> r_{i+1} -> ... -> r_j reaches `metres`. Independent of any rigid alignment.

#include <cstddef>
#include <span>

#include "antslam/eval/association.hpp"
#include "antslam/eval/statistics.hpp"

namespace antslam::eval {

struct RpeSettings {
  std::size_t frames = 1;  ///< step in associated poses (>= 1); used when metres == 0
  double metres = 0.0;     ///< step as distance travelled along the reference, metres; 0 = frames
};

struct RpeResult {
  RpeSettings settings;           ///< the step used
  ErrorStatistics translation_m;  ///< translational errors |t(E_i)|, metres
  ErrorStatistics rotation_deg;   ///< rotational errors |theta(E_i)|, degrees
};

/// Throws std::invalid_argument on invalid settings (frames == 0, metres negative or not finite)
/// and when no pair of associated poses is a step apart.
RpeResult rpe(std::span<const PosePair> pairs, const RpeSettings& settings);

}  // namespace antslam::eval
