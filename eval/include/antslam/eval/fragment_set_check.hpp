#pragma once
// A fragment set checked against a reference trajectory: is each alignment N(mu_i, Sigma_i)
// and each loop closure N(mu_H, Sigma_H) right, and which revisits did the frontend close?
//
// Fragment i's frame F_i is the pose of its first scan, so its reference pose is the reference
// pose at that scan's time stamp. The true alignment is F_{i-1}^-1 F_i; the true hypothesis of
// a closure (a, b) with anchor A (a fixed point of F_b) is F_a^-1 F_b A. A closure is correct
// if its mean H is within max_translation and max_rotation of the truth (the frontend's
// figure of "wrong closures", docs/frontend.md). Fragment b revisits fragment a
// (b - a >= min_fragment_gap) if a reference pose of one of b's scans lies within
// revisit_distance of one of a's; recall is the share of revisiting fragments b that have a
// correct closure (a', b) with any earlier a' (the loop closer keeps at most one closure per b).

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::eval {

struct FragmentSetCheckSettings {
  double max_dt = 0.02;              ///< seconds, stamp tolerance of reference lookups
  double max_translation = 0.3;      ///< metres; a closure further off is wrong
  double max_rotation = 0.0524;      ///< radians (3 deg); a closure turned more is wrong
  double revisit_distance = 1.0;     ///< metres between reference poses that make a revisit
  std::size_t min_fragment_gap = 3;  ///< b - a at least this for a revisit (as the loop closer)
};

/// A Gaussian of the set (alignment or closure) against its true value.
struct GaussianCheck {
  std::size_t from = 0;            ///< fragment a (closures) or i - 1 (alignments)
  std::size_t to = 0;              ///< fragment b (closures) or i (alignments)
  bool has_reference = false;      ///< both frames had a reference pose; else nothing below
  double translation_error = 0.0;  ///< metres, |mean - truth| in translation
  double rotation_error = 0.0;     ///< radians, |mean - truth| in heading
  double mahalanobis = 0.0;        ///< of the truth under the Gaussian (standard deviations)
  bool correct = false;            ///< within max_translation and max_rotation
};

struct FragmentSetCheck {
  std::vector<GaussianCheck> alignments;  ///< one per fragment after the first
  std::vector<GaussianCheck> closures;    ///< one per closure of the set, in order
  std::size_t checked_closures = 0;       ///< closures with reference poses at both frames
  std::size_t correct_closures = 0;       ///< of them, correct
  std::size_t revisits = 0;               ///< fragments that revisit an earlier fragment
  std::size_t revisits_closed = 0;        ///< of them, with a correct closure
  /// correct / checked closures (none checked: nothing to say).
  std::optional<double> precision() const;
  /// closed / revisits (no revisit: nothing to say).
  std::optional<double> recall() const;
};

/// Checks every alignment and closure of `set` against `reference` (both trajectories by time
/// stamp; the set's fragments must carry their scans' trajectories). Throws
/// std::invalid_argument if a fragment has no trajectory or the settings are nonsensical.
FragmentSetCheck check_fragment_set(const slam::FragmentSet& set, const slam::Trajectory& reference,
                                    const FragmentSetCheckSettings& settings = {});

/// The check as JSON: counts, precision, recall and every closure (translation in metres,
/// rotation in degrees).
nlohmann::json to_json(const FragmentSetCheck& check);

}  // namespace antslam::eval
