#include "antslam/frontend/report.hpp"

#include <stdexcept>

namespace antslam::frontend {

using nlohmann::json;

json pose_json(const slam::Pose2& p) { return json::array({p.x, p.y, p.theta}); }

json covariance_json(const Eigen::Matrix3d& c) {
  json rows = json::array();
  for (int r = 0; r < 3; ++r) rows.push_back(json::array({c(r, 0), c(r, 1), c(r, 2)}));
  return rows;
}

json gaussian_json(const slam::Gaussian2& g) {
  return {{"mean", pose_json(g.mean())}, {"covariance", covariance_json(g.covariance())}};
}

std::string_view to_string(AlignmentCovariance covariance) {
  return covariance == AlignmentCovariance::exit_scan ? "exit-scan" : "accumulated";
}

AlignmentCovariance parse_alignment_covariance(std::string_view name) {
  for (const AlignmentCovariance c :
       {AlignmentCovariance::accumulated, AlignmentCovariance::exit_scan})
    if (to_string(c) == name) return c;
  throw std::invalid_argument("unknown alignment covariance '" + std::string(name) +
                              "' (accumulated, exit-scan)");
}

json input_json(const std::string& log_path, const LaserLog& log, const FrontendSettings& s,
                const MapRenderSettings& map) {
  return {{"log", log_path},
          {"scans", log.scans.size()},
          {"beams", log.scans.front().ranges.size()},
          {"skipped_messages", log.skipped_messages},
          {"settings",
           {{"fragment_length_m", s.fragmentation.length},
            {"samples", s.fragmentation.samples},
            {"seed", s.fragmentation.seed},
            {"alignment", to_string(s.fragmentation.covariance)},
            {"covariance_scale", s.fragmentation.covariance_scale},
            {"temperature", s.matcher.temperature},
            {"closures", s.closure.enabled},
            {"closure_min_score", s.closure.min_score},
            {"closure_max_second_ratio", s.closure.max_second_ratio},
            {"closure_temperature", s.closure.temperature},
            {"map_resolution_m", map.resolution}}}};
}

json result_json(const FrontendResult& r) {
  json fragments = json::array();
  for (std::size_t i = 0; i < r.fragments.size(); ++i) {
    const FragmentRecord& f = r.fragments[i];
    const slam::Fragment& s = r.fragment_set.fragments[i];
    json entry = {{"index", i},
                  {"first_scan", f.first_scan},
                  {"scans", f.scan_count},
                  {"length_m", f.length},
                  {"frame", pose_json(f.frame)},
                  {"exit", pose_json(s.exit)},
                  {"samples", s.samples.size()}};
    if (s.alignment) entry["alignment"] = gaussian_json(*s.alignment);
    fragments.push_back(entry);
  }
  json closures = json::array();
  for (const slam::LoopClosure& c : r.fragment_set.closures)
    closures.push_back({{"from", c.from},
                        {"to", c.to},
                        {"anchor", pose_json(c.anchor)},
                        {"hypothesis", gaussian_json(c.hypothesis)}});
  json attempts = json::array();
  for (const ClosureAttempt& a : r.attempts)
    attempts.push_back({{"from", a.from},
                        {"to", a.to},
                        {"ellipse_mahalanobis2", a.mahalanobis},
                        {"prior", pose_json(a.prior)},
                        {"prior_covariance", covariance_json(a.prior_covariance)},
                        {"found", pose_json(a.match.pose)},
                        {"score", a.match.score},
                        {"second_score", a.match.second_score},
                        {"accepted", a.match.accepted},
                        {"reason", a.match.reason},
                        {"seconds", a.seconds}});
  json fallbacks = json::array();
  for (std::size_t i = 0; i < r.scans.size(); ++i)
    if (!r.scans[i].matched_by_scan())
      fallbacks.push_back({{"scan", i},
                           {"stamp", r.trajectory[i].stamp},
                           {"status", frontend::to_string(r.scans[i].status)},
                           {"prior_mahalanobis", r.scans[i].prior_mahalanobis},
                           {"inlier_fraction", r.scans[i].inlier_fraction}});
  return {{"stats",
           {{"unmatched_scans", r.stats.unmatched},
            {"recovered_scans", r.stats.recovered},
            {"diverged_scans", r.stats.diverged},
            {"odometry_along_flat_scans", r.stats.odometry_along_flat}}},
          {"matcher_fallbacks", fallbacks},
          {"fragments", fragments},
          {"closures", closures},
          {"closure_attempts", attempts}};
}

}  // namespace antslam::frontend
