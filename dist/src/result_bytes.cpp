#include "antslam/dist/result_bytes.hpp"

#include <span>
#include <type_traits>

namespace antslam::dist {

// Sent as their bytes (dist/byte_stream.hpp): all ranks of a run share one architecture, and
// these types have no padding, whose bytes would be unset (so equal results could differ).
static_assert(sizeof(slam::Scores) == 2 * sizeof(double));
static_assert(sizeof(slam::Pose2) == 3 * sizeof(double));
static_assert(sizeof(slam::ConvergencePoint) == 4 * sizeof(double));
static_assert(sizeof(aco::ColonySettings) == 7 * sizeof(double));

namespace {

template <class T>
void write_values(dist::ByteWriter& out, const std::vector<T>& vs) {
  out.values(std::span<const T>(vs));
}

// Field by field: a bool and an optional leave padding between the fields.
void write_settings(dist::ByteWriter& out, const aco::RunSettings& s) {
  out.optional(s.variant);
  out.value(s.rho);
  out.value(s.colony);
  out.value(static_cast<std::uint8_t>(s.local_search));
  out.value(s.backend);
  out.value(s.threads);
}

aco::RunSettings read_settings(dist::ByteReader& in) {
  aco::RunSettings s;
  s.variant = in.optional<aco::Variant>();
  s.rho = in.value<double>();
  s.colony = in.value<aco::ColonySettings>();
  s.local_search = in.value<std::uint8_t>() != 0;
  s.backend = in.value<aco::BackendKind>();
  s.threads = in.value<std::size_t>();
  return s;
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
  out.optional(r.colony, write_settings);
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
  if (in.value<std::uint8_t>() != 0) r.colony = read_settings(in);
  return r;
}

void write(dist::ByteWriter& out, const tsp::ExperimentRun& r) {
  out.text(r.instance);
  out.value(r.cities);
  out.value(r.variant);
  out.value(r.threads);
  out.value(r.seed);
  out.value(r.length);
  out.optional(r.optimum);
  write_values(out, r.result.best.path);
  out.value(r.result.best.cost);
  out.value(r.result.iterations);
  out.value(r.result.best_iteration);
  out.value(r.result.elapsed_s);
  out.value(r.result.time_to_best_s);
  out.value(r.result.reason);
  write_settings(out, r.result.settings);
}

tsp::ExperimentRun read_experiment_run(dist::ByteReader& in) {
  tsp::ExperimentRun r;
  r.instance = in.text();
  r.cities = in.value<std::size_t>();
  r.variant = in.value<aco::Variant>();
  r.threads = in.value<std::size_t>();
  r.seed = in.value<std::uint64_t>();
  r.length = in.value<double>();
  r.optimum = in.optional<double>();
  r.result.best.path = in.values<std::uint32_t>();
  r.result.best.cost = in.value<double>();
  r.result.iterations = in.value<std::uint64_t>();
  r.result.best_iteration = in.value<std::uint64_t>();
  r.result.elapsed_s = in.value<double>();
  r.result.time_to_best_s = in.value<double>();
  r.result.reason = in.value<aco::StopReason>();
  r.result.settings = read_settings(in);
  return r;
}

}  // namespace antslam::dist
