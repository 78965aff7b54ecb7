// antslam odometry LOG -o FILE: the odometry-only baseline. The robot poses a CARMEN log's
// scans carry (the FLASER odom fields, ROBOTLASER1's robot pose) as a TUM trajectory.

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "antslam/frontend/laser_log.hpp"
#include "antslam/io/output_files.hpp"
#include "antslam/slamgraph/trajectory.hpp"
#include "commands.hpp"
#include "output_options.hpp"

namespace antslam::cli {

namespace {

struct OdometryOptions {
  std::filesystem::path log;
  std::filesystem::path out;
};

void run(const OdometryOptions& o) {
  io::OutputFiles outputs;
  outputs.add(o.out);
  const frontend::LaserLog log = frontend::read_carmen_file(o.log);
  frontend::require_time_order(log);
  slam::Trajectory odometry;
  for (const frontend::LaserScan& scan : log.scans) odometry.push_back({scan.stamp, scan.odometry});
  outputs.write(o.out, [&](std::ostream& out) { slam::write_tum(out, odometry); });
  outputs.commit();
  std::printf("%s: %zu scans, odometry path %.1f m; wrote %s\n", o.log.string().c_str(),
              odometry.size(), slam::path_length(odometry), o.out.string().c_str());
}

}  // namespace

void add_odometry_command(CLI::App& app) {
  auto options = std::make_shared<OdometryOptions>();
  CLI::App* cmd = app.add_subcommand(
      "odometry", "Write the odometry of a CARMEN log's scans as a TUM trajectory (baseline)");
  cmd->add_option("log", options->log, "CARMEN log (.clf/.log, may be gzipped)")->required();
  add_output_option(*cmd, options->out, "TUM trajectory to write (required)", {"--out"});
  cmd->callback([options] {
    require_output(!options->out.empty(), "--output");
    run(*options);
  });
}

}  // namespace antslam::cli
