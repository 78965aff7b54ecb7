// antslam synth: a synthetic fragment set with known ground truth (slamgraph/synth.hpp).

#include <CLI/CLI.hpp>

#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "antslam/io/memory.hpp"
#include "antslam/io/output_files.hpp"
#include "antslam/slamgraph/fragment_set_io.hpp"
#include "antslam/slamgraph/synth.hpp"
#include "commands.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

using Settings = slam::SynthSettings;

struct SynthOptions {
  std::string preset;
  std::string output;
  Settings given;  ///< values from the command line
  /// For every setting option: copies the given value over the preset's if it was given.
  std::vector<std::function<void(Settings&, const Settings&)>> overrides;
};

/// An option that sets one field of SynthSettings, overriding the preset when given.
template <class T>
void add_setting(CLI::App& cmd, SynthOptions& o, const std::string& name, T Settings::*field,
                 const std::string& help, const CLI::Validator& check) {
  CLI::Option* option =
      cmd.add_option(name, o.given.*field, help)->check(check)->capture_default_str();
  o.overrides.push_back([option, field](Settings& s, const Settings& given) {
    if (option->count() > 0) s.*field = given.*field;
  });
}

void run(const SynthOptions& o) {
  Settings s = o.preset.empty() ? Settings{} : slam::synth_preset(o.preset);
  for (const auto& override_setting : o.overrides) override_setting(s, o.given);
  io::OutputFiles outputs;
  outputs.add(o.output);
  io::require_memory("-n " + std::to_string(s.fragments) + " -m " + std::to_string(s.samples) +
                         " (the fragment set)",
                     slam::fragment_set_bytes(s.fragments, s.samples, s.trajectory_poses));
  const slam::FragmentSet set = slam::synthesize(s);
  outputs.write(o.output, [&](std::ostream& out) { slam::write_fragment_set(out, set); });
  outputs.commit();
  std::printf("wrote %s: %zu fragments, %zu samples each, %zu loop closure(s)\n", o.output.c_str(),
              set.fragments.size(), s.samples, set.closures.size());
}

}  // namespace

void add_synth_command(CLI::App& app) {
  auto o = std::make_shared<SynthOptions>();
  CLI::App* cmd = app.add_subcommand(
      "synth", "Write a synthetic fragment set with ground truth (a simulated loop)");
  cmd->add_option("--preset", o->preset,
                  "paper9, paper15 or paper24 (the paper's sizes, M = 20); other options "
                  "override it");
  cmd->add_option("-o,--output", o->output, "fragment-set JSON to write")->required();
  add_setting(*cmd, *o, "-n,--fragments", &Settings::fragments, "number of fragments N",
              count_in(2, slam::kMaxSynthFragments));
  add_setting(*cmd, *o, "-m,--samples", &Settings::samples, "samples per alignment M",
              count_in(1, slam::kMaxSynthSamples));
  add_setting(*cmd, *o, "--loop-length", &Settings::loop_length_m, "loop perimeter, m",
              finite_in(0.0, 1e6));
  add_setting(*cmd, *o, "--aspect", &Settings::aspect, "width / height of the loop",
              finite_in(1e-3, 1e3));
  add_setting(*cmd, *o, "--laps", &Settings::laps, "times around the loop (> 1: more closures)",
              count_in(1, 1000));
  add_setting(*cmd, *o, "--sigma-xy", &Settings::sigma_xy, "alignment std-dev of x, y, m",
              finite_in(0.0, 1e3));
  add_setting(*cmd, *o, "--sigma-theta", &Settings::sigma_theta, "alignment std-dev of theta, rad",
              finite_in(0.0, 10.0));
  add_setting(*cmd, *o, "--correlation", &Settings::correlation,
              "correlation of x, y, theta in (-0.5, 1)", finite_in(-0.5, 1.0));
  add_setting(*cmd, *o, "--closure-sigma-xy", &Settings::closure_sigma_xy,
              "hypothesis std-dev of x, y, m", finite_in(0.0, 1e3));
  add_setting(*cmd, *o, "--closure-sigma-theta", &Settings::closure_sigma_theta,
              "hypothesis std-dev of theta, rad", finite_in(0.0, 10.0));
  add_setting(*cmd, *o, "--revisit-radius", &Settings::revisit_radius_m,
              "laps > 1: frames closer than this close a loop, m", finite_in(0.0, 1e6));
  add_setting(*cmd, *o, "--trajectory-poses", &Settings::trajectory_poses,
              "robot poses kept per fragment", count_in(0, 10000));
  add_setting(*cmd, *o, "--seed", &Settings::seed, "seed of every random draw",
              non_negative_integer());
  cmd->add_flag("--noise-free", o->given.noise_free, "means and hypotheses equal the ground truth");
  o->overrides.push_back(
      [](Settings& s, const Settings& given) { s.noise_free = given.noise_free; });
  cmd->callback([o] { run(*o); });
}

}  // namespace antslam::cli
