// antslam fragment-set LOG -o SET.json: the laser frontend (paper Sec. III-A) on a CARMEN log,
// written as the fragment set the optimizer reads (docs/fragment-set-format.md). Every fragment
// carries its scans' poses in its own frame, so `antslam optimize SET.json --tum-out FILE`
// writes the corrected trajectory of every scan: F_i (optimized, eq. 8) * pose in F_i.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>

#include "antslam/frontend/laser_log.hpp"
#include "antslam/io/errors.hpp"
#include "antslam/io/output_files.hpp"
#include "antslam/io/progress.hpp"
#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/fragment_set_io.hpp"
#include "antslam/slamgraph/trajectory.hpp"
#include "commands.hpp"
#include "frontend_options.hpp"
#include "output_options.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

struct FragmentSetOptions {
  std::filesystem::path log;
  std::filesystem::path out;
  std::filesystem::path trajectory;
  FrontendOptions frontend;
};

void run(FragmentSetOptions o) {
  resolve(o.frontend);
  frontend::validate(o.frontend.settings);  // before reading the log
  io::OutputFiles outputs;
  outputs.add(o.out);
  if (!o.trajectory.empty()) outputs.add(o.trajectory);
  const frontend::LaserLog log = read_laser_log(o.log, o.frontend.sensor);
  if (!o.trajectory.empty()) frontend::require_time_order(log);
  io::Progress progress;
  const frontend::FrontendResult result = io::in_context_of(o.log, [&] {
    frontend::FrontendResult r = run_frontend(log, o.frontend.settings, progress);
    slam::validate(r.fragment_set);  // e.g. no loop closure found: say so, write nothing
    return r;
  });
  progress.clear();
  outputs.write(o.out,
                [&](std::ostream& out) { slam::write_fragment_set(out, result.fragment_set); });
  if (!o.trajectory.empty())
    outputs.write(o.trajectory,
                  [&](std::ostream& out) { slam::write_tum(out, result.trajectory); });
  outputs.commit();
  std::printf("%s: %zu scans, %zu fragments, %zu loop closures; wrote %s\n", o.log.string().c_str(),
              log.scans.size(), result.fragment_set.fragments.size(),
              result.fragment_set.closures.size(), o.out.string().c_str());
}

}  // namespace

void add_fragment_set_command(CLI::App& app) {
  auto options = std::make_shared<FragmentSetOptions>();
  FragmentSetOptions& o = *options;
  CLI::App* cmd = app.add_subcommand(
      "fragment-set",
      "Frontend of a CARMEN log written as a fragment set (with each fragment's scan poses) for "
      "`antslam optimize`");
  cmd->add_option("log", o.log, "CARMEN log (.clf/.log, may be gzipped)")->required();
  add_output_option(*cmd, o.out, "fragment-set JSON to write (required)", {"--out"});
  cmd->add_option("--seed", o.frontend.settings.fragmentation.seed, "seed of the samples")
      ->check(non_negative_integer())
      ->capture_default_str();
  cmd->add_option("--trajectory", o.trajectory,
                  "also write the scan matcher's trajectory (TUM): the pre-solution baseline");
  add_frontend_options(*cmd, o.frontend);
  cmd->callback([options] {
    require_output(!options->out.empty(), "--output");
    run(*options);
  });
}

}  // namespace antslam::cli
