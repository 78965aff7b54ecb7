// antslam outliers: a g2o pose graph with false loop closures appended (slamgraph/outliers.hpp),
// and the list of the false ones beside it.

#include <CLI/CLI.hpp>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "antslam/io/errors.hpp"
#include "antslam/io/output_files.hpp"
#include "antslam/slamgraph/chain.hpp"
#include "antslam/slamgraph/g2o.hpp"
#include "antslam/slamgraph/outliers.hpp"
#include "commands.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

struct OutliersOptions {
  std::string input;
  std::string output;
  std::string kind = "random";
  slam::OutlierSettings s;
};

/// The most false closures one call adds (a count beyond it is a typing error).
constexpr std::uint64_t kMaxOutliers = 10'000'000;

void run(OutliersOptions o) {
  o.s.kind = *slam::parse_outlier_kind(o.kind);  // --kind is checked at parse time
  io::OutputFiles outputs;
  const std::filesystem::path graph_out = outputs.add(o.output);
  const std::filesystem::path list = outputs.add(slam::outliers_path_of(o.output));
  const slam::PoseGraph graph = slam::read_g2o_file(o.input);
  const slam::SpoiledGraph spoiled = io::in_context_of(o.input, [&] {
    slam::split_sessions(graph, o.input);  // what the robust back ends refuse, refused early
    return slam::add_outliers(graph, o.s);
  });
  outputs.write(graph_out, [&](std::ostream& out) { slam::write_g2o(out, spoiled.graph); });
  outputs.write(list, [&](std::ostream& out) { slam::write_outlier_pairs(out, spoiled.outliers); });
  outputs.commit();
  std::printf("wrote %s: %zu vertices, %zu edges, %zu false loop closures (%s, seed %llu)\n",
              o.output.c_str(), spoiled.graph.vertices.size(), spoiled.graph.edges.size(),
              spoiled.outliers.size(), o.kind.c_str(), static_cast<unsigned long long>(o.s.seed));
  std::printf("wrote %s\n", list.string().c_str());
}

}  // namespace

void add_outliers_command(CLI::App& app) {
  auto o = std::make_shared<OutliersOptions>();
  CLI::App* cmd = app.add_subcommand(
      "outliers", "Add false loop closures to a g2o pose graph (Suenderhauf & Protzel 2012)");
  cmd->add_option("input", o->input, "g2o pose graph (VERTEX_SE2, EDGE_SE2)")->required();
  cmd->add_option("-o,--output", o->output,
                  "g2o file to write; OUT.outliers.txt lists the false "
                  "closures (`i j` a line)")
      ->required();
  cmd->add_option("--count", o->s.count, "false loop closures to add")
      ->check(count_in(0, kMaxOutliers))
      ->capture_default_str();
  std::vector<std::string> kinds;
  std::string help = "how their vertices are drawn:";
  for (const slam::OutlierKindInfo& k : slam::kOutlierKinds) {
    kinds.emplace_back(k.name);
    help += " " + std::string(k.name) + " (" + std::string(k.summary) + ")";
  }
  cmd->add_option("--kind", o->kind, help)->check(CLI::IsMember(kinds))->capture_default_str();
  cmd->add_option("--group-size", o->s.group_size, "closures per group (group kinds)")
      ->check(count_in(1, kMaxOutliers))
      ->capture_default_str();
  cmd->add_option("--seed", o->s.seed, "seed of every draw")
      ->check(non_negative_integer())
      ->capture_default_str();
  cmd->callback([o] { run(*o); });
}

}  // namespace antslam::cli
