#include "antslam/tsp/experiment.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <stdexcept>
#include <string>

#include "antslam/aco/backend_kind.hpp"
#include "antslam/tsp/optima.hpp"
#include "antslam/tsp/tsplib.hpp"

namespace antslam::tsp {

void validate(const ExperimentSettings& s) {
  if (!s.termination.bounded())
    throw std::invalid_argument("experiment: set a budget (iterations, time or CPU time)");
  if (s.instances.empty()) throw std::invalid_argument("experiment: no instance");
  if (s.variants.empty()) throw std::invalid_argument("experiment: no variant");
  if (s.threads.empty()) throw std::invalid_argument("experiment: no thread count");
  if (s.seeds == 0) throw std::invalid_argument("experiment: seeds must be >= 1");
  for (const std::size_t threads : s.threads) aco::resolve(s.solver.backend, threads);
  if (s.only)
    for (const std::size_t i : *s.only)
      if (i >= run_count(s))
        throw std::invalid_argument("experiment: run " + std::to_string(i) + " of " +
                                    std::to_string(run_count(s)));
}

std::size_t run_count(const ExperimentSettings& s) {
  return s.instances.size() * s.variants.size() * s.threads.size() * s.seeds;
}

double ExperimentRun::excess_percent() const {
  return optimum ? 100.0 * (length / *optimum - 1.0) : NAN;
}

std::vector<ExperimentRun> run_experiment(const ExperimentSettings& settings,
                                          const ExperimentObserver& observer) {
  validate(settings);
  const std::size_t total = run_count(settings);
  const std::size_t per_instance = total / settings.instances.size();
  std::vector<std::size_t> wanted(total);
  for (std::size_t i = 0; i < total; ++i) wanted[i] = i;
  if (settings.only) wanted = *settings.only;
  std::vector<ExperimentRun> runs(wanted.size());
  std::vector<bool> finished(wanted.size(), false);
  const auto finished_runs = [&] {  // in `wanted` order
    std::vector<ExperimentRun> kept;
    for (std::size_t w = 0; w < runs.size(); ++w)
      if (finished[w]) kept.push_back(std::move(runs[w]));
    return kept;
  };
  // Instance-major, so that each instance is read once for the runs that need it.
  for (std::size_t k = 0; k < settings.instances.size(); ++k) {
    const auto of_instance = [&](std::size_t i) { return i / per_instance == k; };
    if (std::none_of(wanted.begin(), wanted.end(), of_instance)) continue;
    const std::filesystem::path& path = settings.instances[k];
    const TspProblem problem(read_instance(path), settings.problem);
    const std::optional<double> optimum = known_optimum(path);
    aco::Termination termination = settings.termination;
    if (settings.stop_at_optimum && optimum) termination.target_cost = *optimum;
    for (std::size_t w = 0; w < wanted.size(); ++w) {
      const std::size_t index = wanted[w];
      if (!of_instance(index)) continue;
      // index = ((k * variants + v) * threads + t) * seeds + s
      const std::size_t s = index % settings.seeds;
      const std::size_t t = index / settings.seeds % settings.threads.size();
      const std::size_t v =
          index / settings.seeds / settings.threads.size() % settings.variants.size();
      SolverSettings solver = settings.solver;
      solver.aco.variant = settings.variants[v];
      solver.aco.seed = settings.first_seed + s;
      solver.threads = settings.threads[t];
      ExperimentRun r{problem.instance().name(),
                      problem.size(),
                      settings.variants[v],
                      settings.threads[t],
                      solver.aco.seed,
                      0.0,
                      optimum,
                      {}};
      r.result = solve(problem, solver, termination, [&](const aco::IterationReport& report) {
        if (observer) observer(index, total, r, report);
      });
      if (r.result.reason == aco::StopReason::interrupted) return finished_runs();  // cut short
      r.length = problem.instance().tour_length(r.result.best.path);
      runs[w] = std::move(r);
      finished[w] = true;
      if (termination.stop.stop_requested()) return finished_runs();
    }
  }
  return runs;
}

std::filesystem::path resolve_instance(const std::string& name,
                                       const std::filesystem::path& data_dir) {
  if (std::filesystem::is_regular_file(name)) return name;
  const std::filesystem::path path = data_dir / (name + ".tsp");
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error("'" + name + "' is neither a file nor " + path.string());
  return path;
}

void write_runs_csv(std::ostream& out, std::span<const ExperimentRun> runs,
                    std::string_view local_search) {
  out << "instance,cities,variant,local_search,threads,seed,best_length,optimum,excess_percent,"
         "hit_optimum,iterations,best_iteration,time_to_best_s,elapsed_s,stop_reason\n"
      << std::setprecision(10);
  for (const ExperimentRun& r : runs)
    out << r.instance << ',' << r.cities << ',' << aco::to_string(r.variant) << ',' << local_search
        << ',' << r.threads << ',' << r.seed << ',' << r.length << ','
        << (r.optimum ? *r.optimum : NAN) << ',' << r.excess_percent() << ','
        << (r.hit_optimum() ? 1 : 0) << ',' << r.result.iterations << ',' << r.result.best_iteration
        << ',' << r.result.time_to_best_s << ',' << r.result.elapsed_s << ','
        << aco::to_string(r.result.reason) << '\n';
}

void write_summary_markdown(std::ostream& out, std::span<const ExperimentRun> runs,
                            std::string_view local_search) {
  out << "| instance | n | variant | local search | threads | runs | best | mean | worst | "
         "mean excess % | hit optimum | mean time to best (s) |\n"
      << "|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  std::vector<bool> done(runs.size(), false);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (done[i]) continue;
    std::vector<const ExperimentRun*> group;
    for (std::size_t j = i; j < runs.size(); ++j)
      if (!done[j] && runs[j].instance == runs[i].instance && runs[j].variant == runs[i].variant &&
          runs[j].threads == runs[i].threads) {
        group.push_back(&runs[j]);
        done[j] = true;
      }
    double best = INFINITY, worst = 0.0, sum = 0.0, sum_excess = 0.0, sum_ttb = 0.0;
    int hits = 0;
    for (const ExperimentRun* r : group) {
      best = std::min(best, r->length);
      worst = std::max(worst, r->length);
      sum += r->length;
      sum_excess += r->excess_percent();
      sum_ttb += r->result.time_to_best_s;
      hits += r->hit_optimum() ? 1 : 0;
    }
    const auto count = static_cast<double>(group.size());
    const ExperimentRun& r = *group.front();
    out << "| " << r.instance << " | " << r.cities << " | " << aco::to_string(r.variant) << " | "
        << local_search << " | " << r.threads << " | " << group.size() << " | " << std::fixed
        << std::setprecision(0) << best << " | " << std::setprecision(1) << sum / count << " | "
        << std::setprecision(0) << worst << " | ";
    if (r.optimum) {
      out << std::setprecision(3) << sum_excess / count << " | " << hits << "/" << group.size();
    } else {
      out << "- | -";
    }
    out << " | " << std::setprecision(2) << sum_ttb / count << " |\n";
  }
}

}  // namespace antslam::tsp
