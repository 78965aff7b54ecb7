// antslam tsp-generate: a seeded random-uniform EUC_2D instance in TSPLIB format.

#include <iostream>
#include <memory>
#include <string>

#include "antslam/io/output_files.hpp"
#include "antslam/tsp/generator.hpp"
#include "antslam/tsp/tsplib.hpp"
#include "commands.hpp"
#include "output_options.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

struct GenerateCommand {
  std::size_t cities = 1000;
  std::uint64_t seed = 1;
  double side = 1.0e6;
  std::string kind = "uniform";
  tsp::ClusterSettings clusters;
  std::filesystem::path out;
};

}  // namespace

void add_tsp_generate_command(CLI::App& app) {
  auto c = std::make_shared<GenerateCommand>();
  CLI::App* sub = app.add_subcommand(
      "tsp-generate",
      "Write a random instance in [0, side]^2, EUC_2D: uniform or clustered (DIMACS portgen / "
      "portcgen)");
  sub->add_option("--cities", c->cities, "number of cities")
      ->check(count_in(3, 10'000'000))
      ->capture_default_str();
  sub->add_option("--seed", c->seed, "seed of the coordinates")
      ->check(non_negative_integer())
      ->capture_default_str();
  sub->add_option("--side", c->side, "coordinates are integers in [0, side]")
      ->check(finite_in(1.0, 1.0e9))
      ->capture_default_str();
  sub->add_option("--kind", c->kind, "uniform, or clustered around cities/10 normal centres")
      ->check(CLI::IsMember({"uniform", "clustered"}))
      ->capture_default_str();
  sub->add_option("--cities-per-cluster", c->clusters.cities_per_cluster,
                  "clustered: cities / this many centres")
      ->check(finite_in(1.0, 1e9))
      ->capture_default_str();
  sub->add_option("--spread", c->clusters.spread,
                  "clustered: standard deviation around a centre, in units of side/sqrt(cities)")
      ->check(finite_in(1e-6, 1e6))
      ->capture_default_str();
  add_output_option(*sub, c->out, "TSPLIB file to write (required)", {"--out"});
  sub->callback([c] {
    require_output(!c->out.empty(), "--output");
    io::OutputFiles outputs;
    outputs.add(c->out);
    const tsp::Instance instance =
        c->kind == "clustered"
            ? tsp::random_clustered_instance(c->cities, c->seed, c->side, c->clusters)
            : tsp::random_uniform_instance(c->cities, c->seed, c->side);
    outputs.write(c->out, [&](std::ostream& out) { tsp::write_instance(out, instance); });
    outputs.commit();
    std::cout << "wrote " << c->out.string() << " (" << instance.name() << ", " << instance.size()
              << " cities)\n";
  });
}

}  // namespace antslam::cli
