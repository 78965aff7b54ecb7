// antslam g2o: a 2D pose graph (g2o or TORO lines, slamgraph/g2o.hpp) as a fragment set, or as a
// pose graph in the other format.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>

#include "antslam/io/errors.hpp"
#include "antslam/io/memory.hpp"
#include "antslam/io/output_files.hpp"
#include "antslam/slamgraph/fragment_set_io.hpp"
#include "antslam/slamgraph/g2o.hpp"
#include "commands.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

struct G2oOptions {
  std::string input;
  std::string output;
  std::string reference;
  slam::G2oImportSettings import;
};

void run(const G2oOptions& o) {
  io::OutputFiles outputs;
  outputs.add(o.output);
  const slam::PoseGraph graph = slam::read_g2o_file(o.input);
  if (slam::is_pose_graph_file(o.output)) {
    outputs.write(o.output,
                  [&](std::ostream& out) { slam::write_pose_graph(out, graph, o.output); });
    outputs.commit();
    std::printf("wrote %s: %zu vertices%s, %zu edges\n", o.output.c_str(), graph.vertices.size(),
                graph.vertices_from_file ? "" : " (composed along the edges)", graph.edges.size());
    return;
  }
  io::require_memory("-m " + std::to_string(o.import.samples) + " (the samples)",
                     slam::fragment_set_bytes(graph.vertices.size(), o.import.samples, 0));
  slam::FragmentSet set = io::in_context_of(
      o.input, [&] { return slam::fragment_set_from_g2o(graph, o.import, o.input); });
  set.reference = slam::reference_poses(set.fragments.size(), {}, o.reference);
  io::in_context_of(o.input, [&] { slam::validate(set); });
  outputs.write(o.output, [&](std::ostream& out) { slam::write_fragment_set(out, set); });
  outputs.commit();
  std::printf("wrote %s: %zu fragments (vertices), %zu alignments, %zu loop closures, M = %zu\n",
              o.output.c_str(), set.fragments.size(), set.layer_count(), set.closures.size(),
              o.import.samples);
}

}  // namespace

void add_g2o_command(CLI::App& app) {
  auto o = std::make_shared<G2oOptions>();
  CLI::App* cmd = app.add_subcommand(
      "g2o", "Convert a 2D pose graph (g2o or TORO) into a fragment set, or into the other format");
  cmd->add_option("input", o->input, "pose graph (VERTEX_SE2/EDGE_SE2/FIX or VERTEX2/EDGE2)")
      ->required();
  cmd->add_option("-o,--output", o->output,
                  "fragment-set JSON to write; a .g2o or .graph (TORO) name writes the pose graph "
                  "in that format")
      ->required();
  cmd->add_option("-m,--samples", o->import.samples, "samples drawn per alignment (eq. 7)")
      ->check(count_in(1, kMaxSamples))
      ->capture_default_str();
  cmd->add_option("--seed", o->import.seed, "seed of the samples")
      ->check(non_negative_integer())
      ->capture_default_str();
  cmd->add_option("--reference", o->reference,
                  "ground-truth poses stored with the set (.g2o, .graph, .tum or `x y theta` "
                  "lines)");
  cmd->callback([o] { run(*o); });
}

}  // namespace antslam::cli
