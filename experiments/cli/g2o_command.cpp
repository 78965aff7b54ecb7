// antslam g2o: a g2o pose graph (VERTEX_SE2 / EDGE_SE2) as a fragment set (slamgraph/g2o.hpp).

#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cli/errors.hpp"
#include "cli/memory.hpp"
#include "cli/output_files.hpp"
#include "commands.hpp"
#include "slamgraph/fragment_set_io.hpp"
#include "slamgraph/g2o.hpp"
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
  OutputFiles outputs;
  outputs.add(o.output);
  const slam::PoseGraph graph = slam::read_g2o_file(o.input);
  std::vector<slam::Pose2> reference;
  if (!o.reference.empty()) reference = slam::read_reference_poses(o.reference);
  require_memory("-m " + std::to_string(o.import.samples) + " (the samples)",
                 slam::fragment_set_bytes(graph.vertices.size(), o.import.samples, 0));
  slam::FragmentSet set =
      in_context_of(o.input, [&] { return slam::fragment_set_from_g2o(graph, o.import, o.input); });
  if (!o.reference.empty()) {
    set.reference = std::move(reference);
    if (set.reference.size() != set.fragments.size())
      throw std::runtime_error(o.reference + ": has " + std::to_string(set.reference.size()) +
                               " poses, the graph " + std::to_string(set.fragments.size()));
  }
  in_context_of(o.input, [&] { slam::validate(set); });
  outputs.write(o.output, [&](std::ostream& out) { slam::write_fragment_set(out, set); });
  outputs.commit();
  std::printf("wrote %s: %zu fragments (vertices), %zu alignments, %zu loop closures, M = %zu\n",
              o.output.c_str(), set.fragments.size(), set.layer_count(), set.closures.size(),
              o.import.samples);
}

}  // namespace

void add_g2o_command(CLI::App& app) {
  auto o = std::make_shared<G2oOptions>();
  CLI::App* cmd = app.add_subcommand("g2o", "Convert a g2o 2D pose graph into a fragment set");
  cmd->add_option("input", o->input, "g2o file (VERTEX_SE2, EDGE_SE2)")->required();
  cmd->add_option("-o,--output", o->output, "fragment-set JSON to write")->required();
  cmd->add_option("-m,--samples", o->import.samples, "samples drawn per alignment (eq. 7)")
      ->check(count_in(1, kMaxSamples))
      ->capture_default_str();
  cmd->add_option("--seed", o->import.seed, "seed of the samples")
      ->check(non_negative_integer())
      ->capture_default_str();
  cmd->add_option("--reference", o->reference,
                  "ground-truth poses stored with the set (.g2o, .tum or `x y theta` lines)");
  cmd->callback([o] { run(*o); });
}

}  // namespace antslam::cli
