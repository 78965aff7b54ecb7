// antslam qap: solve one QAPLIB instance with an ACO variant (MAX-MIN Ant System with pair-swap
// local search by default, MMAS-QAP), print a summary, optionally write a JSON summary.

#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>

#include "antslam/aco/backend_kind.hpp"
#include "antslam/aco/variant.hpp"
#include "antslam/io/json_output.hpp"
#include "antslam/io/output_files.hpp"
#include "antslam/qap/qaplib.hpp"
#include "antslam/qap/solver.hpp"
#include "backend_option.hpp"
#include "commands.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

struct QapCommand {
  std::filesystem::path instance;
  std::string variant = "mmas";
  std::string local_search = "pairswap";  ///< pairswap or none
  std::string backend = "auto";
  qap::SolverSettings solver;
  std::uint64_t iterations = 0;
  double time_s = 0.0;
  std::filesystem::path json_out;
};

qap::SolverSettings solver_settings(const QapCommand& c) {
  qap::SolverSettings s = c.solver;
  const auto variant = aco::parse_variant(c.variant);
  if (!variant) throw std::invalid_argument("--variant: unknown variant '" + c.variant + "'");
  s.aco.variant = *variant;
  s.local_search = c.local_search == "pairswap";
  s.backend = parse_backend_option(c.backend);
  aco::resolve(s.backend, s.threads);  // serial on more than one thread fails here, up front
  return s;
}

/// "1 2 3": the location of every facility, 1-based as QAPLIB's solutions.
nlohmann::json one_based(std::span<const std::uint32_t> assignment) {
  nlohmann::json locations = nlohmann::json::array();
  for (std::uint32_t l : assignment) locations.push_back(l + 1);
  return locations;
}

void run(const QapCommand& c) {
  const qap::SolverSettings settings = solver_settings(c);
  io::OutputFiles outputs;
  if (!c.json_out.empty()) outputs.add(c.json_out);
  const qap::QapProblem problem(qap::read_qaplib(c.instance));
  aco::Termination termination{.max_iterations = c.iterations, .time_limit_s = c.time_s};
  if (!termination.bounded()) {
    termination.time_limit_s = 10.0;
    std::cout << "no budget given: stopping after 10 s (set --iterations or --time)\n";
  }
  const aco::RunResult result = qap::solve(problem, settings, termination);
  const aco::RunSettings& ran = result.settings;
  const std::int64_t cost = problem.instance().cost(result.best.path);
  std::cout << "instance     " << problem.instance().name() << " (" << problem.size()
            << " facilities)\n"
            << "algorithm    " << c.variant << ", " << ran.colony.ants << " ants, rho " << ran.rho
            << ", " << (settings.local_search ? "pair-swap local search" : "no local search")
            << ", seed " << settings.aco.seed << ", " << ran.threads << " thread(s) ("
            << aco::to_string(ran.backend) << ")\n"
            << "best cost    " << cost << "\n"
            << "iterations   " << result.iterations
            << " (stopped: " << aco::to_string(result.reason) << ")\n"
            << std::fixed << std::setprecision(3) << "time         " << result.elapsed_s
            << " s, best found after " << result.time_to_best_s << " s (iteration "
            << result.best_iteration << ")\n";
  if (c.json_out.empty()) return;
  const nlohmann::json j = {{"instance", problem.instance().name()},
                            {"facilities", problem.size()},
                            {"variant", c.variant},
                            {"ants", ran.colony.ants},
                            {"rho", ran.rho},
                            {"local_search", settings.local_search},
                            {"seed", settings.aco.seed},
                            {"backend", std::string(aco::to_string(ran.backend))},
                            {"threads", ran.threads},
                            {"best_cost", cost},
                            {"assignment", one_based(result.best.path)},
                            {"iterations", result.iterations},
                            {"stop_reason", std::string(aco::to_string(result.reason))},
                            {"elapsed_s", result.elapsed_s},
                            {"time_to_best_s", result.time_to_best_s}};
  outputs.write(c.json_out, io::json_text(j));
  outputs.commit();
}

}  // namespace

void add_qap_command(CLI::App& app) {
  auto command = std::make_shared<QapCommand>();
  CLI::App* sub = app.add_subcommand(
      "qap", "Solve a QAPLIB instance (default: MAX-MIN Ant System with pair-swap local search)");
  sub->add_option("-i,--instance", command->instance, "QAPLIB .dat file")->required();
  sub->add_option("--variant", command->variant, "ACO variant")
      ->check(CLI::IsMember(aco::variant_names()))
      ->capture_default_str();
  sub->add_option("--local-search", command->local_search,
                  "local search applied to the ants' assignments")
      ->check(CLI::IsMember({"none", "pairswap"}))
      ->capture_default_str();
  sub->add_option("--ants", command->solver.aco.ants,
                  "ants per iteration (0: 5 for mmas with local search, else the variant's)")
      ->check(count_in(0, 1'000'000))
      ->capture_default_str();
  sub->add_option("--iterations", command->iterations, "iteration budget (0: none)")
      ->check(non_negative_integer());
  sub->add_option("--time", command->time_s, "wall-clock budget in seconds (0: none)")
      ->check(finite_in(0.0, 1e9));
  sub->add_option("--seed", command->solver.aco.seed, "seed of every random choice")
      ->check(non_negative_integer())
      ->capture_default_str();
  sub->add_option("--threads", command->solver.threads, "threads building ants (0: all cores)")
      ->check(count_in(0, kMaxThreads))
      ->capture_default_str();
  add_backend_option(*sub, command->backend);
  sub->add_option("--json", command->json_out, "write a JSON summary of the run");
  sub->callback([command] { run(*command); });
}

}  // namespace antslam::cli
