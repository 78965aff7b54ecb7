#include "optimizer_options.hpp"

#include <cstdint>
#include <limits>
#include <string>

#include "backend_option.hpp"
#include "validators.hpp"

namespace antslam::cli {

void add_optimizer_options(CLI::App& command, OptimizerOptions& o) {
  constexpr auto kMaxInt = static_cast<std::uint64_t>(std::numeric_limits<int>::max());
  slam::OptimizeSettings& s = o.settings;
  std::string methods;
  for (const slam::Method m : slam::all_methods())
    methods += (methods.empty() ? "" : ", ") + std::string(slam::to_string(m));
  command.add_option("--method", o.method, methods)->capture_default_str();
  add_backend_option(command, o.backend);
  command.add_option("--seed", s.seed, "seed of every random choice")
      ->check(non_negative_integer())
      ->capture_default_str();
  command.add_option("--iterations", s.iterations, "ACO iterations / random rounds")
      ->check(non_negative_integer())
      ->capture_default_str();
  // --time, as in every command; --time-limit, the earlier spelling, stays a hidden alias.
  command.add_option("--time-limit", s.time_limit_s)->check(finite_in(0.0, 1e9))->group("");
  command
      .add_option("--time", s.time_limit_s,
                  "wall-clock budget per trial (ants, NLopt and Ceres together), s (0 = none)")
      ->check(finite_in(0.0, 1e9))
      ->capture_default_str();
  command.add_option("--ants", s.aco.ants, "ants per iteration (0 = the variant's default)")
      ->check(count_in(0, slam::kMaxAnts))
      ->capture_default_str();
  command.add_option("--rho", s.aco.rho, "evaporation rate (0 = the variant's default)")
      ->check(finite_in(0.0, 1.0))
      ->capture_default_str();
  command.add_option("--p0", s.aco.p0, "hybrid: probability of a uniform choice")
      ->check(finite_in(0.0, 1.0))
      ->capture_default_str();
  command.add_option("--q0", s.aco.q0, "acs: probability of the greedy choice")
      ->check(finite_in(0.0, 1.0))
      ->capture_default_str();
  command.add_option("--nlopt-algorithm", o.nlopt_algorithm, "lbfgs, slsqp or bobyqa")
      ->capture_default_str();
  command
      .add_option("--bound-sigmas", s.refine.bound_sigmas,
                  "NLopt box: samples' bounding box widened by this many sigmas")
      ->check(finite_in(0.0, 1e6))
      ->capture_default_str();
  command
      .add_option("--max-evaluations", s.refine.max_evaluations,
                  "NLopt evaluations per refinement (per stage when graduated)")
      ->check(count_in(1, kMaxInt))
      ->capture_default_str();
  command
      .add_option("--lbfgs-memory", s.refine.lbfgs_memory, "NLopt L-BFGS stored correction pairs")
      ->check(count_in(1, 1000))
      ->capture_default_str();
  command.add_flag("--no-graduated", o.no_graduated,
                   "NLopt refinement of eq. 10 only, without the graduated (widened-kernel) one");
  command.add_flag("--refine-each", s.refine_each_improvement,
                   "hybrid+nlopt: refine every new global-best ant, not only the final one");
  command.add_option("--ceres-iterations", s.ceres.max_iterations, "Ceres iterations")
      ->check(count_in(1, kMaxInt))
      ->capture_default_str();
  command.add_option("--max-paths", s.max_exhaustive_paths, "exhaustive: refuse larger trees")
      ->check(non_negative_integer())
      ->capture_default_str();
}

slam::OptimizeSettings optimize_settings(const OptimizerOptions& o) {
  slam::OptimizeSettings s = o.settings;
  s.method = slam::parse_method(o.method);
  s.refine.algorithm = slam::parse_refine_algorithm(o.nlopt_algorithm);
  s.refine.graduated = !o.no_graduated;
  s.backend = parse_backend_option(o.backend);
  return s;
}

}  // namespace antslam::cli
