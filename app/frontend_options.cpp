#include "frontend_options.hpp"

#include "antslam/frontend/report.hpp"
#include "validators.hpp"

namespace antslam::cli {

void add_frontend_options(CLI::App& command, FrontendOptions& o) {
  command
      .add_option("--fragment-length", o.settings.fragmentation.length,
                  "metres travelled per fragment")
      ->check(finite_in(0.0, 1e6))
      ->capture_default_str();
  command
      .add_option("--samples", o.settings.fragmentation.samples,
                  "samples M per fragment alignment (eq. 7)")
      ->check(count_in(1, kMaxSamples))
      ->capture_default_str();
  command
      .add_option("--alignment", o.alignment,
                  "alignment covariance: accumulated (eqs. 5-6 of every scan, composed) or "
                  "exit-scan (the paper: eqs. 5-6 of the exit scan)")
      ->check(CLI::IsMember({"accumulated", "exit-scan"}))
      ->capture_default_str();
  command
      .add_option("--covariance-scale", o.settings.fragmentation.covariance_scale,
                  "multiplies the alignment covariance")
      ->check(finite_in(0.0, 1e6))
      ->capture_default_str();
  command
      .add_option("--temperature", o.settings.matcher.temperature,
                  "scan-matcher likelihood temperature")
      ->check(finite_in(0.0, 1e6))
      ->capture_default_str();
  command
      .add_option("--divergence-sigmas", o.settings.matcher.divergence_sigmas,
                  "a scan match further from the odometry prediction (standard deviations) "
                  "is kept only if it fits --trusted-fit of its points, else the odometry is")
      ->check(finite_in(0.0, 1e6))
      ->capture_default_str();
  command
      .add_option("--trusted-fit", o.settings.matcher.trusted_fit,
                  "share of a scan's points that must fit for a match to overrule the odometry")
      ->check(finite_in(0.0, 1.0))
      ->capture_default_str();
  add_sensor_options(command, o.sensor);
  command.add_flag("--no-closures", o.no_closures, "do not look for loop closures");
  command
      .add_option("--closure-min-score", o.settings.closure.min_score,
                  "mean point likelihood a loop closure needs, in (0, 1]")
      ->check(finite_in(0.0, 1.0))
      ->capture_default_str();
  command
      .add_option("--closure-max-second", o.settings.closure.max_second_ratio,
                  "reject a closure if a separate peak scores this share of the best")
      ->check(finite_in(0.0, 1.0))
      ->capture_default_str();
  command
      .add_option("--closure-neighbours", o.settings.closure.target_neighbours,
                  "fragments on each side of a closure candidate that join its map")
      ->check(count_in(0, 20))
      ->capture_default_str();
  command
      .add_option("--closure-temperature", o.settings.closure.temperature,
                  "divides the loop-closure log-likelihood (widens N(mu_H, Sigma_H))")
      ->check(finite_in(0.0, 1e6))
      ->capture_default_str();
}

void add_map_options(CLI::App& command, FrontendOptions& o) {
  command.add_option("--resolution", o.map.resolution, "map cell size, metres")
      ->check(finite_in(1e-4, 1e3))
      ->capture_default_str();
}

void resolve(FrontendOptions& o) {
  o.settings.fragmentation.covariance = frontend::parse_alignment_covariance(o.alignment);
  o.settings.closure.enabled = !o.no_closures;
}

frontend::FrontendResult run_frontend(const frontend::LaserLog& log,
                                      const frontend::FrontendSettings& settings,
                                      io::Progress& progress) {
  return frontend::run_frontend(log, settings, [&](const frontend::FrontendProgress& p) {
    progress.update(frontend::to_string(p));
  });
}

}  // namespace antslam::cli
