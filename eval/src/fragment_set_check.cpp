#include "antslam/eval/fragment_set_check.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "antslam/eval/association.hpp"

namespace antslam::eval {

namespace {

void validate(const FragmentSetCheckSettings& s) {
  const auto positive = [](double v) { return v > 0.0 && std::isfinite(v); };
  if (!(s.max_dt >= 0.0 && std::isfinite(s.max_dt)) || !positive(s.max_translation) ||
      !positive(s.max_rotation) || !positive(s.revisit_distance) || s.min_fragment_gap < 1)
    throw std::invalid_argument(
        "fragment set check: tolerances must be positive and finite, the gap at least 1");
}

GaussianCheck check(std::size_t from, std::size_t to, const slam::Gaussian2& gaussian,
                    const std::optional<slam::Pose2>& truth, const FragmentSetCheckSettings& s) {
  GaussianCheck out{from, to};
  if (!truth) return out;
  const Eigen::Vector3d r = gaussian.residual(*truth);
  out.has_reference = true;
  out.translation_error = std::hypot(r.x(), r.y());
  out.rotation_error = std::abs(r.z());
  out.mahalanobis = std::sqrt(gaussian.mahalanobis_squared(*truth));
  out.correct = out.translation_error <= s.max_translation && out.rotation_error <= s.max_rotation;
  return out;
}

/// Reference positions of the scans of every fragment (those with a reference pose).
std::vector<std::vector<Eigen::Vector2d>> reference_positions(const slam::FragmentSet& set,
                                                              const slam::Trajectory& reference,
                                                              double max_dt) {
  std::vector<std::vector<Eigen::Vector2d>> out(set.fragments.size());
  for (std::size_t i = 0; i < set.fragments.size(); ++i)
    for (const slam::StampedPose& p : set.fragments[i].trajectory)
      if (const auto k = find_stamp(reference, p.stamp, max_dt))
        out[i].push_back(reference[*k].pose.translation());
  return out;
}

bool revisits(const std::vector<Eigen::Vector2d>& b, const std::vector<Eigen::Vector2d>& a,
              double distance) {
  for (const Eigen::Vector2d& p : b)
    for (const Eigen::Vector2d& q : a)
      if ((p - q).squaredNorm() <= distance * distance) return true;
  return false;
}

}  // namespace

std::optional<double> FragmentSetCheck::precision() const {
  if (checked_closures == 0) return std::nullopt;
  return static_cast<double>(correct_closures) / static_cast<double>(checked_closures);
}

std::optional<double> FragmentSetCheck::recall() const {
  if (revisits == 0) return std::nullopt;
  return static_cast<double>(revisits_closed) / static_cast<double>(revisits);
}

FragmentSetCheck check_fragment_set(const slam::FragmentSet& set, const slam::Trajectory& reference,
                                    const FragmentSetCheckSettings& s) {
  validate(s);
  // F_i in the reference: the reference pose at its first scan's stamp.
  std::vector<std::optional<slam::Pose2>> frames(set.fragments.size());
  for (std::size_t i = 0; i < set.fragments.size(); ++i) {
    const slam::Trajectory& t = set.fragments[i].trajectory;
    if (t.empty())
      throw std::invalid_argument("fragment set check: fragment " + std::to_string(i) +
                                  " has no scan trajectory (time stamps are needed)");
    if (const auto k = find_stamp(reference, t.front().stamp, s.max_dt))
      frames[i] = reference[*k].pose;
  }
  const auto relative = [&](std::size_t a, std::size_t b) -> std::optional<slam::Pose2> {
    if (!frames[a] || !frames[b]) return std::nullopt;
    return slam::between(*frames[a], *frames[b]);
  };
  FragmentSetCheck out;
  for (std::size_t i = 1; i < set.fragments.size(); ++i)
    out.alignments.push_back(check(i - 1, i, *set.fragments[i].alignment, relative(i - 1, i), s));
  std::vector<bool> closed(set.fragments.size(), false);
  for (const slam::LoopClosure& c : set.closures) {
    std::optional<slam::Pose2> truth = relative(c.from, c.to);
    if (truth) truth = *truth * c.anchor;
    out.closures.push_back(check(c.from, c.to, c.hypothesis, truth, s));
    const GaussianCheck& g = out.closures.back();
    out.checked_closures += g.has_reference ? 1U : 0U;
    out.correct_closures += g.correct ? 1U : 0U;
    if (g.correct) closed[c.to] = true;
  }
  const auto positions = reference_positions(set, reference, s.max_dt);
  for (std::size_t b = s.min_fragment_gap; b < set.fragments.size(); ++b)
    for (std::size_t a = 0; a + s.min_fragment_gap <= b; ++a)
      if (revisits(positions[b], positions[a], s.revisit_distance)) {
        ++out.revisits;
        out.revisits_closed += closed[b] ? 1U : 0U;
        break;
      }
  return out;
}

nlohmann::json to_json(const FragmentSetCheck& check) {
  constexpr double degrees = 180.0 / std::numbers::pi;
  nlohmann::json closures = nlohmann::json::array();
  for (const GaussianCheck& c : check.closures) {
    nlohmann::json entry = {{"from", c.from}, {"to", c.to}, {"has_reference", c.has_reference}};
    if (c.has_reference) {
      entry["translation_error_m"] = c.translation_error;
      entry["rotation_error_deg"] = c.rotation_error * degrees;
      entry["mahalanobis"] = c.mahalanobis;
      entry["correct"] = c.correct;
    }
    closures.push_back(entry);
  }
  nlohmann::json inconsistent = nlohmann::json::array();
  double worst = 0.0;
  for (const GaussianCheck& a : check.alignments) {
    if (a.has_reference && a.mahalanobis > 3.0)
      inconsistent.push_back({{"fragment", a.to},
                              {"translation_error_m", a.translation_error},
                              {"rotation_error_deg", a.rotation_error * degrees},
                              {"mahalanobis", a.mahalanobis}});
    worst = std::max(worst, a.mahalanobis);
  }
  const auto optional = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
  };
  return {{"closures_checked", check.checked_closures},
          {"closures_correct", check.correct_closures},
          {"precision", optional(check.precision())},
          {"revisits", check.revisits},
          {"revisits_closed", check.revisits_closed},
          {"recall", optional(check.recall())},
          {"alignments_beyond_3_sigma", inconsistent.size()},
          {"alignments_beyond_3_sigma_list", inconsistent},
          {"alignment_mahalanobis_max", worst},
          {"closures", closures}};
}

}  // namespace antslam::eval
