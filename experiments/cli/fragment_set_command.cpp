// antslam fragment-set LOG -o SET.json: the laser frontend (paper Sec. III-A) on a CARMEN log,
// written as the fragment set the optimizer reads (docs/fragment-set-format.md). Every fragment
// carries its scans' poses in its own frame, so `antslam optimize SET.json --tum-out FILE`
// writes the corrected trajectory of every scan: F_i (optimized, eq. 8) * pose in F_i.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/atomic_file.hpp"
#include "cli/progress.hpp"
#include "commands.hpp"
#include "frontend/frontend.hpp"
#include "frontend/laser_log.hpp"
#include "sensor_options.hpp"
#include "slamgraph/fragment_set.hpp"
#include "slamgraph/fragment_set_io.hpp"
#include "slamgraph/trajectory.hpp"

namespace antslam::cli {

namespace {

struct FragmentSetOptions {
  std::filesystem::path log;
  std::filesystem::path out;
  std::filesystem::path trajectory;
  SensorOptions sensor;
  frontend::FrontendSettings settings;
};

void run(FragmentSetOptions o) {
  frontend::Frontend frontend(o.settings, o.log.filename().string());  // validates the settings
  const frontend::LaserLog log = frontend::read_carmen_file(o.log, o.sensor.overrides());
  Progress progress;
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    frontend.add_scan(log.scans[i]);
    progress.update("fragment-set: scan " + std::to_string(i + 1) + "/" +
                    std::to_string(log.scans.size()));
  }
  const frontend::FrontendResult result = frontend.finish();
  progress.clear();
  slam::validate(result.fragment_set);  // e.g. no loop closure found: say so, write nothing
  write_atomically(o.out,
                   [&](std::ostream& out) { slam::write_fragment_set(out, result.fragment_set); });
  if (!o.trajectory.empty())
    write_atomically(o.trajectory,
                     [&](std::ostream& out) { slam::write_tum(out, result.trajectory); });
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
  cmd->add_option("-o,--out", o.out, "fragment-set JSON to write")->required();
  cmd->add_option("--fragment-length", o.settings.fragmentation.length,
                  "metres travelled per fragment")
      ->capture_default_str();
  cmd->add_option("--samples", o.settings.fragmentation.samples,
                  "samples M per fragment alignment (eq. 7)")
      ->capture_default_str();
  cmd->add_option("--seed", o.settings.fragmentation.seed, "seed of the samples")
      ->capture_default_str();
  cmd->add_option("--trajectory", o.trajectory,
                  "also write the scan matcher's trajectory (TUM): the pre-solution baseline");
  add_sensor_options(*cmd, o.sensor);
  cmd->callback([options] { run(*options); });
}

}  // namespace antslam::cli
