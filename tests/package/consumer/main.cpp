// Uses every installed library once; exits 0 if each gives the value computed here by hand.
#include <antslam/aco/synthetic_layered.hpp>
#include <antslam/aco/variants.hpp>
#include <antslam/baselines/tinyslam.hpp>
#include <antslam/clique/exact.hpp>
#include <antslam/eval/statistics.hpp>
#include <antslam/frontend/frontend.hpp>
#include <antslam/mapping/optimize_map.hpp>
#include <antslam/slamgraph/synth.hpp>
#include <antslam/tsp/generator.hpp>
#include <antslam/tsp/problem.hpp>
#include <antslam/tsp/solver.hpp>
#include <cstdio>
#include <vector>

int main() {
  namespace as = antslam;
  // Engine: a tiny layered problem against enumeration of its 64 choices.
  const as::aco::SyntheticLayeredProblem problem(3, 4, 1);
  as::aco::Parameters p;
  p.variant = as::aco::Variant::hybrid;
  const auto result = as::aco::solve(problem, p, {.max_iterations = 200});
  double best = 1e300;
  for (std::uint32_t a = 0; a < 4; ++a)
    for (std::uint32_t b = 0; b < 4; ++b)
      for (std::uint32_t c = 0; c < 4; ++c) {
        const std::uint32_t choice[3] = {a, b, c};
        const double cost = problem.cost(choice);
        best = cost < best ? cost : best;
      }
  int failures = result.best.cost == best ? 0 : 1;

  // TSP: a tour of 20 random cities visits each city once.
  const as::tsp::TspProblem tsp(as::tsp::random_uniform_instance(20, 3));
  const auto tour = as::tsp::solve(tsp, {}, {.max_iterations = 5});
  failures += tour.best.path.size() == 20 ? 0 : 1;

  // SLAM graph and mapping: the paper's N = 9 set has one loop closure, whose residual under
  // its own ground truth is small.
  const as::slam::FragmentSet set = as::slam::synthesize(as::slam::synth_preset("paper9"));
  const auto residuals = as::mapping::closure_residuals(set, set.reference);
  failures += residuals.size() == set.closures.size() ? 0 : 1;

  // Clique: the maximum clique of a triangle with a pendant vertex is the triangle.
  const std::vector<as::clique::Edge> edges{{0, 1}, {1, 2}, {0, 2}, {2, 3}};
  failures +=
      as::clique::maximum_clique_exact(as::clique::Graph(4, edges)).clique.weight == 3.0 ? 0 : 1;

  // Frontend, baselines, eval: settings that validate, statistics of {1, 3}.
  as::frontend::validate(as::frontend::FrontendSettings{});
  as::baselines::validate(as::baselines::TinySlamSettings{});
  const std::vector<double> values{1.0, 3.0};
  failures += as::eval::mean_std(values).mean == 2.0 ? 0 : 1;

  std::printf("consumer: best %.6f, optimum %.6f, %d failure(s)\n", result.best.cost, best,
              failures);
  return failures;
}
