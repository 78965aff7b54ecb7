#pragma once
// --backend, the same for every command that runs ants: one of aco::kBackends.

#include <CLI/CLI.hpp>

#include <string>

#include "antslam/aco/backend_kind.hpp"

namespace antslam::cli {

/// Registers --backend on `command`, storing the name in `name`.
void add_backend_option(CLI::App& command, std::string& name);

/// The backend a checked --backend value names.
aco::BackendKind parse_backend_option(const std::string& name);

}  // namespace antslam::cli
