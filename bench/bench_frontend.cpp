// Scans per second of the laser frontend on the bundled real logs (target: >= 200 scans/s on
// one thread), and the accuracy of its scan-matcher trajectory against the logs' reference
// trajectories (RMSE after a rigid SE(2) alignment over matched timestamps; the final target
// after optimisation is < 0.30 m on mit-csail and < 0.50 m on intel-subset).
//
//   build/bench/bench_frontend                      (all)
//   build/bench/bench_frontend --benchmark_filter=mit --benchmark_repetitions=3

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include <cmath>
#include <map>
#include <string>

#include "frontend/frontend.hpp"
#include "frontend/laser_log.hpp"
#include "frontend/scan_matcher.hpp"
#include "slamgraph/trajectory.hpp"

namespace {

using namespace antslam;

/// RMSE of the estimate's positions against the reference at equal timestamps (to 0.1 ms),
/// after the rigid motion that best aligns them (Horn/Umeyama in 2D, no scale).
double aligned_rmse(const slam::Trajectory& estimate, const slam::Trajectory& reference) {
  std::map<long long, Eigen::Vector2d> at;
  for (const slam::StampedPose& p : estimate)
    at[std::llround(p.stamp * 1e4)] = p.pose.translation();
  std::vector<Eigen::Vector2d> a, b;
  for (const slam::StampedPose& r : reference) {
    const auto it = at.find(std::llround(r.stamp * 1e4));
    if (it == at.end()) continue;
    a.push_back(it->second);
    b.push_back(r.pose.translation());
  }
  if (a.size() < 2) return NAN;
  Eigen::Vector2d ma = Eigen::Vector2d::Zero(), mb = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < a.size(); ++i) {
    ma += a[i] / static_cast<double>(a.size());
    mb += b[i] / static_cast<double>(b.size());
  }
  double dot = 0.0, cross = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Eigen::Vector2d p = a[i] - ma, q = b[i] - mb;
    dot += p.dot(q);
    cross += p.x() * q.y() - p.y() * q.x();
  }
  const double angle = std::atan2(cross, dot);
  const Eigen::Rotation2Dd rotation(angle);
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    sum += (rotation * (a[i] - ma) + mb - b[i]).squaredNorm();
  return std::sqrt(sum / static_cast<double>(a.size()));
}

void run_log(benchmark::State& state, const std::string& name, bool closures) {
  const std::string dir = ANTSLAM_DATA_DIR "/laser/";
  const frontend::LaserLog log = frontend::read_carmen_file(dir + name + ".clf");
  const slam::Trajectory reference = slam::read_tum_file(dir + name + ".ref.tum");
  frontend::FrontendSettings settings;
  settings.closure.enabled = closures;
  frontend::FrontendResult result;
  for (auto _ : state) {
    result = frontend::run_frontend(log, settings);
    benchmark::DoNotOptimize(result.trajectory.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(log.scans.size()));
  state.counters["scans_per_s"] = benchmark::Counter(
      static_cast<double>(log.scans.size()) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
  state.counters["rmse_m"] = aligned_rmse(result.trajectory, reference);
  state.counters["fragments"] = static_cast<double>(result.fragments.size());
  state.counters["closures"] = static_cast<double>(result.fragment_set.closures.size());
  state.counters["matching_s"] = result.stats.matching_seconds;
  state.counters["closure_s"] = result.stats.closure_seconds;
}

void BM_Frontend_MitCsail(benchmark::State& state) { run_log(state, "mit-csail", true); }
void BM_Frontend_IntelSubset(benchmark::State& state) { run_log(state, "intel-subset", true); }
void BM_ScanMatcher_MitCsail(benchmark::State& state) { run_log(state, "mit-csail", false); }
void BM_ScanMatcher_IntelSubset(benchmark::State& state) { run_log(state, "intel-subset", false); }

BENCHMARK(BM_Frontend_MitCsail)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_Frontend_IntelSubset)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_ScanMatcher_MitCsail)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_ScanMatcher_IntelSubset)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
