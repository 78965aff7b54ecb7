#pragma once
// The one spelling of output options across the subcommands:
//   -o, --output FILE|PREFIX  the command's main output (a file, or a prefix of several files)
//   --out-dir DIR             the folder of a command that writes several files
// Further files are named by their format (--g2o-out, --tum-out, --tour-out, --json, ...).
// The spellings of earlier versions stay accepted as hidden aliases (not in --help).

#include <CLI/CLI.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace antslam::cli {

/// Adds -o/--output for `target`, and `aliases` (earlier spellings) hidden.
template <class T>
CLI::Option* add_output_option(CLI::App& command, T& target, const std::string& description,
                               const std::vector<std::string>& aliases = {}) {
  for (const std::string& alias : aliases) command.add_option(alias, target)->group("");
  return command.add_option("-o,--output", target, description);
}

/// Adds --out-dir for `target`, and the earlier --out hidden.
template <class T>
CLI::Option* add_out_dir_option(CLI::App& command, T& target, const std::string& description) {
  command.add_option("--out", target)->group("");
  return command.add_option("--out-dir", target, description);
}

/// Throws std::invalid_argument "NAME is required" unless the option was given (a required
/// option with hidden aliases cannot be marked required in CLI11).
void require_output(bool given, std::string_view name);

}  // namespace antslam::cli
