// antslam tsp-generate: a seeded random-uniform EUC_2D instance in TSPLIB format.

#include <iostream>
#include <memory>

#include "cli/atomic_file.hpp"
#include "commands.hpp"
#include "output_options.hpp"
#include "tsp/generator.hpp"
#include "tsp/tsplib.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

struct GenerateCommand {
  std::size_t cities = 1000;
  std::uint64_t seed = 1;
  double side = 1.0e6;
  std::filesystem::path out;
};

}  // namespace

void add_tsp_generate_command(CLI::App& app) {
  auto c = std::make_shared<GenerateCommand>();
  CLI::App* sub = app.add_subcommand(
      "tsp-generate", "Write a random instance: cities uniform in [0, side]^2, EUC_2D");
  sub->add_option("--cities", c->cities, "number of cities")
      ->check(CLI::Range(std::size_t{3}, std::size_t{10'000'000}))
      ->capture_default_str();
  sub->add_option("--seed", c->seed, "seed of the coordinates")
      ->check(non_negative_integer())
      ->capture_default_str();
  sub->add_option("--side", c->side, "coordinates are integers in [0, side]")
      ->check(finite_in(1.0, 1.0e9))
      ->capture_default_str();
  add_output_option(*sub, c->out, "TSPLIB file to write (required)", {"--out"});
  sub->callback([c] {
    require_output(!c->out.empty(), "--output");
    const tsp::Instance instance = tsp::random_uniform_instance(c->cities, c->seed, c->side);
    write_atomically(c->out, [&](std::ostream& out) { tsp::write_instance(out, instance); });
    std::cout << "wrote " << c->out.string() << " (" << instance.name() << ", " << instance.size()
              << " cities)\n";
  });
}

}  // namespace antslam::cli
