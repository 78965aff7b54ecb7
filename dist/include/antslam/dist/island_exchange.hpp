#pragma once
// The island model's exchange over a run's processes (aco/islands.hpp): every rank's offers
// (best, iteration-best, stop flag and path of each of its colonies), gathered with the rank's
// outcome so that a rank whose colonies failed makes every rank throw RankFailure at the same
// exchange.

#include "antslam/aco/islands.hpp"
#include "antslam/dist/communicator.hpp"

namespace antslam::dist {

/// The exchange over comm's processes, for aco::IslandSettings' colonies spread over its ranks.
aco::Exchange island_exchange(Communicator& comm);

}  // namespace antslam::dist
