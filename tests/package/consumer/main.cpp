// Solves a tiny layered problem with the installed engine; exits 0 if the optimum is found.
#include <aco/synthetic_layered.hpp>
#include <aco/variants.hpp>
#include <cstdio>

int main() {
  const antslam::aco::SyntheticLayeredProblem problem(3, 4, 1);
  antslam::aco::Parameters p;
  p.variant = antslam::aco::Variant::hybrid;
  const auto result = antslam::aco::solve(problem, p, {.max_iterations = 200});
  double best = 1e300;  // enumerate the 64 choices
  for (std::uint32_t a = 0; a < 4; ++a)
    for (std::uint32_t b = 0; b < 4; ++b)
      for (std::uint32_t c = 0; c < 4; ++c) {
        const std::uint32_t choice[3] = {a, b, c};
        const double cost = problem.cost(choice);
        best = cost < best ? cost : best;
      }
  std::printf("consumer: best %.6f, optimum %.6f\n", result.best.cost, best);
  return result.best.cost == best ? 0 : 1;
}
