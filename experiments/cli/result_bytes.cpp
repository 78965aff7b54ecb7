#include "result_bytes.hpp"

#include <span>
#include <type_traits>

namespace antslam::cli {

// Sent as their bytes (dist/byte_stream.hpp): all ranks of a run share one architecture.
static_assert(std::is_trivially_copyable_v<slam::Scores>);
static_assert(std::is_trivially_copyable_v<slam::Pose2>);
static_assert(std::is_trivially_copyable_v<slam::ConvergencePoint>);
static_assert(std::is_trivially_copyable_v<std::optional<aco::RunSettings>>);
static_assert(std::is_trivially_copyable_v<std::optional<double>>);

namespace {

template <class T>
void write_values(dist::ByteWriter& out, const std::vector<T>& vs) {
  out.values(std::span<const T>(vs));
}

}  // namespace

void write(dist::ByteWriter& out, const slam::OptimizeResult& r) {
  out.value(r.method);
  out.value(r.scores);
  write_values(out, r.choice);
  write_values(out, r.alignments);
  write_values(out, r.frames);
  out.value(r.iterations);
  out.value(r.evaluations);
  out.value(r.elapsed_s);
  out.value(r.time_to_best_s);
  write_values(out, r.convergence);
  out.value(r.colony);
}

slam::OptimizeResult read_optimize_result(dist::ByteReader& in) {
  slam::OptimizeResult r;
  r.method = in.value<slam::Method>();
  r.scores = in.value<slam::Scores>();
  r.choice = in.values<std::uint32_t>();
  r.alignments = in.values<slam::Pose2>();
  r.frames = in.values<slam::Pose2>();
  r.iterations = in.value<std::uint64_t>();
  r.evaluations = in.value<std::uint64_t>();
  r.elapsed_s = in.value<double>();
  r.time_to_best_s = in.value<double>();
  r.convergence = in.values<slam::ConvergencePoint>();
  r.colony = in.value<std::optional<aco::RunSettings>>();
  return r;
}

void write(dist::ByteWriter& out, const tsp::ExperimentRun& r) {
  out.text(r.instance);
  out.value(r.cities);
  out.value(r.variant);
  out.value(r.threads);
  out.value(r.seed);
  out.value(r.length);
  out.value(r.optimum);
  write_values(out, r.result.best.path);
  out.value(r.result.best.cost);
  out.value(r.result.iterations);
  out.value(r.result.best_iteration);
  out.value(r.result.elapsed_s);
  out.value(r.result.time_to_best_s);
  out.value(r.result.reason);
  out.value(r.result.settings);
}

tsp::ExperimentRun read_experiment_run(dist::ByteReader& in) {
  tsp::ExperimentRun r;
  r.instance = in.text();
  r.cities = in.value<std::size_t>();
  r.variant = in.value<aco::Variant>();
  r.threads = in.value<std::size_t>();
  r.seed = in.value<std::uint64_t>();
  r.length = in.value<double>();
  r.optimum = in.value<std::optional<double>>();
  r.result.best.path = in.values<std::uint32_t>();
  r.result.best.cost = in.value<double>();
  r.result.iterations = in.value<std::uint64_t>();
  r.result.best_iteration = in.value<std::uint64_t>();
  r.result.elapsed_s = in.value<double>();
  r.result.time_to_best_s = in.value<double>();
  r.result.reason = in.value<aco::StopReason>();
  r.result.settings = in.value<aco::RunSettings>();
  return r;
}

}  // namespace antslam::cli
