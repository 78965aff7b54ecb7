// The ACO methods of optimize(): the engine's colony on the SlamProblem, and hybrid+nlopt.

#include <optional>

#include "antslam/aco/backend_factory.hpp"
#include "antslam/slamgraph/slam_problem.hpp"
#include "optimize_detail.hpp"

namespace antslam::slam::detail {

namespace {

/// NLopt refinement of discrete paths, keeping the best continuous result.
class PathRefiner {
 public:
  PathRefiner(const FragmentSet& set, const RefineSettings& settings)
      : set_(&set), refiner_(set, settings) {}

  /// Refines the path within `seconds` (0 = no limit); returns the best weight of any refined
  /// path so far.
  double refine(std::span<const std::uint32_t> path, double seconds, std::uint64_t& evaluations) {
    const RefineResult r = refiner_.refine(chosen_alignments(*set_, path), seconds);
    evaluations += static_cast<std::uint64_t>(r.evaluations);
    if (!best_ || r.scores.weight < best_->scores.weight) {
      best_ = r;
      start_.assign(path.begin(), path.end());
    }
    return best_->scores.weight;
  }
  const std::optional<RefineResult>& best() const { return best_; }
  const std::vector<std::uint32_t>& start() const { return start_; }

 private:
  const FragmentSet* set_;
  Refiner refiner_;
  std::optional<RefineResult> best_;
  std::vector<std::uint32_t> start_;
};

}  // namespace

void run_aco(const FragmentSet& set, const OptimizeSettings& settings, Recorder& recorder,
             OptimizeResult& result) {
  const SlamProblem problem(set);
  aco::Parameters p = settings.aco;
  p.variant = aco_variant(settings.method).value();
  p.seed = settings.seed;
  const aco::Termination termination{.max_iterations = settings.iterations,
                                     .time_limit_s = settings.time_limit_s,
                                     .stop = settings.stop};
  const bool refine = settings.method == Method::hybrid_nlopt;
  std::optional<PathRefiner> refiner;
  if (refine) refiner.emplace(set, refine_settings(settings));
  const std::uint64_t ants = aco::colony_settings(p, problem.layer_count(), false, false).ants;
  std::uint64_t refine_evaluations = 0;
  // A refinement gets what is left of the run's budget (ants and refinement share it).
  const auto refine_seconds = [&] {
    return stage_budget(settings.time_limit_s, recorder.elapsed(), settings.refine.time_limit_s);
  };

  const auto observe = [&](const aco::IterationReport& r) {
    if (!r.improved) return;
    double best = r.global_best;
    if (refine && settings.refine_each_improvement)
      best =
          std::min(best, refiner->refine(r.global_best_path, refine_seconds(), refine_evaluations));
    recorder.improve(r.iteration, r.iteration * ants + refine_evaluations, best);
  };
  const aco::RunResult run_result =
      settings.islands
          ? aco::solve_islands(
                problem, p, termination,
                [&] { return aco::make_backend(settings.backend, settings.threads); },
                aco::NoLocalSearch{}, *settings.islands, settings.exchange,
                [&](const aco::IslandReport& r) { observe(r.run); })
                .run
          : aco::with_backend(settings.backend, settings.threads, [&](auto backend) {
              return aco::solve(problem, p, termination, backend, aco::NoLocalSearch{}, observe);
            });
  result.iterations = run_result.iterations;
  result.colony = run_result.settings;
  result.choice = run_result.best.path;
  result.alignments = chosen_alignments(set, result.choice);
  if (refine) {
    // Algorithm 2 returns S_best (line 36); NLopt then refines it continuously (already done
    // when every new global best was refined).
    if (!settings.refine_each_improvement) {
      const double best = refiner->refine(result.choice, refine_seconds(), refine_evaluations);
      recorder.improve(result.iterations, result.iterations * ants + refine_evaluations, best);
    }
    result.choice = refiner->start();
    result.alignments = refiner->best()->alignments;
  }
  result.evaluations = result.iterations * ants + refine_evaluations;
}

}  // namespace antslam::slam::detail
