#include "island_options.hpp"

#include <span>
#include <string>
#include <utility>
#include <vector>

#include "antslam/dist/byte_stream.hpp"
#include "antslam/dist/farm.hpp"
#include "antslam/dist/outcome.hpp"
#include "antslam/io/errors.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {
constexpr std::uint64_t kMaxColonies = 4096;
}  // namespace

void add_island_options(CLI::App& command, IslandOptions& o) {
  command
      .add_option("--colonies", o.colonies,
                  "island model: K colonies exchanging their best solutions (under mpirun -np R: "
                  "R | K, K/R colonies per rank; else all in this process)")
      ->check(count_in(1, kMaxColonies));
  command
      .add_option("--exchange-every", o.exchange_every,
                  "island model: iterations between exchanges of the colonies' best solutions")
      ->check(count_in(1, std::uint64_t{1} << 40U))
      ->capture_default_str();
  command
      .add_option(
          "--topology", o.topology,
          "island model: ring (colony c receives from c-1) or full (from the best other colony)")
      ->check(CLI::IsMember({"ring", "full"}))
      ->capture_default_str();
}

std::optional<aco::IslandSettings> island_settings(const IslandOptions& o,
                                                   const dist::Communicator& comm,
                                                   const std::string& command) {
  const std::size_t ranks = comm.size();
  if (o.colonies == 0 && ranks > 1)
    throw io::UsageError(command + " runs one colony per rank: give --colonies " +
                         std::to_string(ranks) + " (or a multiple of " + std::to_string(ranks) +
                         ") under " + std::to_string(ranks) + " ranks");
  if (o.colonies % ranks != 0)
    throw io::UsageError("--colonies " + std::to_string(o.colonies) + " is not a multiple of the " +
                         std::to_string(ranks) + " ranks");
  if (o.colonies <= 1) return std::nullopt;
  aco::IslandSettings s;
  s.colonies = o.colonies;
  s.exchange_every = o.exchange_every;
  s.topology = *aco::parse_topology(o.topology);  // checked by the option
  s.local = o.colonies / ranks;
  s.first = comm.rank() * s.local;
  return s;
}

}  // namespace antslam::cli
