#include "antslam/slamgraph/graph_optimize.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "antslam/slamgraph/graph_objective.hpp"
#include "antslam/slamgraph/graph_structure.hpp"
#include "graph_ceres.hpp"
#include "nlopt_stages.hpp"
#include "optimize_detail.hpp"

namespace antslam::slam {

namespace {

/// The fragment chain of a graph, for the chain methods.
FragmentSet chain_of(const PoseGraph& graph, const std::string& source,
                     const G2oImportSettings& import) {
  if (graph.fixed.size() > 1)
    throw std::invalid_argument(source + ": the graph fixes " + std::to_string(graph.fixed.size()) +
                                " vertices (FIX lines); the methods on its fragment chain hold "
                                "one, ceres, ceres-robust and nlopt hold them all");
  return fragment_set_from_g2o(graph, import, source);
}

/// A chain method's result, with its frames moved rigidly so that the fixed vertex keeps the
/// graph's pose, and scored over the graph's edges.
OptimizeResult on_graph(OptimizeResult result, const PoseGraph& graph) {
  const std::size_t k = fixed_vertices(graph).front();
  const Pose2 placement = graph.vertices[k] * result.frames[k].inverse();
  for (Pose2& f : result.frames) f = placement * f;
  result.scores = score(graph, result.frames);
  return result;
}

/// NLopt's box: positions within the vertices' bounding box widened by its diagonal (at least
/// 1 m), angles within 2 pi of their start.
void graph_box(const PoseGraph& graph, const std::vector<double>& x, std::vector<double>& lower,
               std::vector<double>& upper) {
  Eigen::Vector2d lo = graph.vertices.front().translation(), hi = lo;
  for (const Pose2& p : graph.vertices) {
    lo = lo.cwiseMin(p.translation());
    hi = hi.cwiseMax(p.translation());
  }
  const double widen = std::max(1.0, (hi - lo).norm());
  lower.resize(x.size());
  upper.resize(x.size());
  for (std::size_t d = 0; d < x.size(); ++d) {
    const int axis = static_cast<int>(d % 3);
    if (axis == 2) {
      lower[d] = x[d] - 2.0 * std::numbers::pi;
      upper[d] = x[d] + 2.0 * std::numbers::pi;
    } else {
      lower[d] = lo[axis] - widen;
      upper[d] = hi[axis] + widen;
    }
  }
}

/// ceres, ceres-robust or nlopt on the graph itself.
OptimizeResult optimize_on_graph(const PoseGraph& graph, const std::string& source,
                                 const OptimizeSettings& settings,
                                 const OptimizeObserver& observer) {
  check_anchored(graph, source);
  OptimizeResult result;
  result.method = settings.method;
  detail::Recorder recorder(result, observer);
  if (settings.method == Method::nlopt) {
    GraphObjective objective(graph);
    const std::vector<double> x = objective.pack(graph.vertices);
    std::vector<double> lower, upper;
    graph_box(graph, x, lower, upper);
    RefineSettings refine = refine_settings(settings);
    refine.time_limit_s =
        detail::stage_budget(settings.time_limit_s, recorder.elapsed(), refine.time_limit_s);
    if (x.empty()) {  // every vertex fixed: nothing to move, and NLopt refuses no unknowns
      result.frames = objective.unpack(x);
    } else {
      const detail::StagedMinimum m =
          detail::NloptStages<GraphObjective>(objective, refine).run(x, lower, upper);
      result.frames = objective.unpack(m.x);
      result.evaluations = static_cast<std::uint64_t>(m.evaluations);
    }
  } else {
    CeresSettings ceres = settings.ceres;
    ceres.time_limit_s =
        detail::stage_budget(settings.time_limit_s, recorder.elapsed(), ceres.time_limit_s);
    const CeresResult c =
        detail::optimize_graph_with_ceres(graph, settings.method == Method::ceres_robust, ceres);
    result.frames = c.frames;
    result.iterations = static_cast<std::uint64_t>(c.iterations);
  }
  result.alignments = relative_alignments(result.frames);
  result.scores = score(graph, result.frames);
  recorder.improve(result.iterations, result.evaluations, result.scores.weight);
  result.elapsed_s = recorder.elapsed();
  return result;
}

void check_graph_settings(const OptimizeSettings& settings) {
  validate(settings);
  if (!settings.initial.empty())
    throw std::invalid_argument(
        "optimize: a pose graph starts from its vertex poses; set those instead of `initial`");
}

}  // namespace

bool needs_fragment_chain(Method m) {
  return m != Method::ceres && m != Method::ceres_robust && m != Method::nlopt;
}

OptimizeResult optimize(const PoseGraph& graph, const std::string& source,
                        const OptimizeSettings& settings, const G2oImportSettings& import,
                        const OptimizeObserver& observer) {
  check_graph_settings(settings);
  if (!needs_fragment_chain(settings.method))
    return optimize_on_graph(graph, source, settings, observer);
  return on_graph(optimize(chain_of(graph, source, import), settings, observer), graph);
}

std::vector<OptimizeResult> run_trials(const PoseGraph& graph, const std::string& source,
                                       const OptimizeSettings& settings,
                                       const G2oImportSettings& import, const TrialSettings& trials,
                                       const TrialsObserver& observer,
                                       const OptimizeObserver& convergence) {
  check_graph_settings(settings);
  if (!needs_fragment_chain(settings.method)) {
    return run_trials(
        [&](const OptimizeSettings& s, const OptimizeObserver& o) {
          return optimize_on_graph(graph, source, s, o);
        },
        settings, trials, observer, convergence);
  }
  std::vector<OptimizeResult> results =
      run_trials(chain_of(graph, source, import), settings, trials, observer, convergence);
  for (OptimizeResult& r : results) r = on_graph(std::move(r), graph);
  return results;
}

}  // namespace antslam::slam
