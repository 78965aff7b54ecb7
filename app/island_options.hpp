#pragma once
// The island model on the command line (--colonies, --exchange-every, --topology) and its
// binding to the run's processes: K colonies over R ranks, R | K, rank r running colonies
// r K/R .. (r+1) K/R - 1; without an MPI launcher all K run in this process.

#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "antslam/aco/islands.hpp"
#include "antslam/dist/communicator.hpp"

namespace antslam::cli {

struct IslandOptions {
  std::size_t colonies = 0;           ///< K; 0: not given
  std::uint64_t exchange_every = 25;  ///< E (docs/mpi-islands.md, "Exchange interval")
  std::string topology = "ring";      ///< ring or full
};

void add_island_options(CLI::App& command, IslandOptions& options);

/// This process's share of the islands, or nothing for a plain one-colony run (no --colonies,
/// or --colonies 1, in a single process). Throws UsageError, the same on every rank, when the
/// run's R processes cannot share the colonies: --colonies not given under R > 1 ranks, or K
/// not a multiple of R. `command` names the subcommand in the message.
std::optional<aco::IslandSettings> island_settings(const IslandOptions& options,
                                                   const dist::Communicator& comm,
                                                   const std::string& command);

}  // namespace antslam::cli
