// antslam synth: a synthetic fragment set with known ground truth (slamgraph/synth.hpp).

#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>

#include "cli/atomic_file.hpp"
#include "commands.hpp"
#include "slamgraph/fragment_set_io.hpp"
#include "slamgraph/synth.hpp"

namespace antslam::cli {

namespace {

struct SynthOptions {
  std::string preset;
  std::string output;
  slam::SynthSettings s;
};

/// Options given on the command line override the preset.
void run(const CLI::App& app, const SynthOptions& o) {
  slam::SynthSettings s = o.preset.empty() ? slam::SynthSettings{} : slam::synth_preset(o.preset);
  const auto given = [&](const char* name) { return app.get_option(name)->count() > 0; };
  if (given("--fragments")) s.fragments = o.s.fragments;
  if (given("--samples")) s.samples = o.s.samples;
  if (given("--loop-length")) s.loop_length_m = o.s.loop_length_m;
  if (given("--aspect")) s.aspect = o.s.aspect;
  if (given("--laps")) s.laps = o.s.laps;
  if (given("--sigma-xy")) s.sigma_xy = o.s.sigma_xy;
  if (given("--sigma-theta")) s.sigma_theta = o.s.sigma_theta;
  if (given("--correlation")) s.correlation = o.s.correlation;
  if (given("--closure-sigma-xy")) s.closure_sigma_xy = o.s.closure_sigma_xy;
  if (given("--closure-sigma-theta")) s.closure_sigma_theta = o.s.closure_sigma_theta;
  if (given("--revisit-radius")) s.revisit_radius_m = o.s.revisit_radius_m;
  if (given("--trajectory-poses")) s.trajectory_poses = o.s.trajectory_poses;
  s.noise_free = o.s.noise_free;
  s.seed = o.s.seed;
  const slam::FragmentSet set = slam::synthesize(s);
  write_atomically(o.output, [&](std::ostream& out) { slam::write_fragment_set(out, set); });
  std::printf("wrote %s: %zu fragments, %zu samples each, %zu loop closure(s)\n", o.output.c_str(),
              set.fragments.size(), s.samples, set.closures.size());
}

}  // namespace

void add_synth_command(CLI::App& app) {
  auto o = std::make_shared<SynthOptions>();
  CLI::App* cmd = app.add_subcommand(
      "synth", "Write a synthetic fragment set with ground truth (a simulated loop)");
  cmd->add_option("--preset", o->preset, "paper9, paper15 or paper24 (the paper's sizes, M = 20)");
  cmd->add_option("-o,--output", o->output, "fragment-set JSON to write")->required();
  cmd->add_option("-n,--fragments", o->s.fragments, "number of fragments N")->capture_default_str();
  cmd->add_option("-m,--samples", o->s.samples, "samples per alignment M")->capture_default_str();
  cmd->add_option("--loop-length", o->s.loop_length_m, "loop perimeter, m")->capture_default_str();
  cmd->add_option("--aspect", o->s.aspect, "width / height of the loop")->capture_default_str();
  cmd->add_option("--laps", o->s.laps, "times around the loop (> 1: several closures)")
      ->capture_default_str();
  cmd->add_option("--sigma-xy", o->s.sigma_xy, "alignment std-dev of x, y, m")
      ->capture_default_str();
  cmd->add_option("--sigma-theta", o->s.sigma_theta, "alignment std-dev of theta, rad")
      ->capture_default_str();
  cmd->add_option("--correlation", o->s.correlation, "correlation of x, y, theta in (-0.5, 1)")
      ->capture_default_str();
  cmd->add_option("--closure-sigma-xy", o->s.closure_sigma_xy, "hypothesis std-dev of x, y, m")
      ->capture_default_str();
  cmd->add_option("--closure-sigma-theta", o->s.closure_sigma_theta,
                  "hypothesis std-dev of theta, rad")
      ->capture_default_str();
  cmd->add_option("--revisit-radius", o->s.revisit_radius_m,
                  "laps > 1: frames closer than this close a loop, m")
      ->capture_default_str();
  cmd->add_option("--trajectory-poses", o->s.trajectory_poses, "robot poses kept per fragment")
      ->capture_default_str();
  cmd->add_flag("--noise-free", o->s.noise_free, "means and hypotheses equal the ground truth");
  cmd->add_option("--seed", o->s.seed, "seed of every random draw")->capture_default_str();
  cmd->callback([cmd, o] { run(*cmd, *o); });
}

}  // namespace antslam::cli
