#pragma once
// Farming independent runs (trials, seeds, jobs) over the processes of a command: run i of
// `count` runs on rank i % size, each rank runs its share, and every rank receives every result
// in run order, so that all ranks go on along the same code path and the root writes what a
// single process would write. A run's seed must depend on its index only, never on the rank.

#include <cstddef>
#include <exception>
#include <span>
#include <stdexcept>
#include <vector>

#include "antslam/dist/byte_stream.hpp"
#include "antslam/dist/communicator.hpp"
#include "antslam/dist/outcome.hpp"
#include "antslam/io/errors.hpp"

namespace antslam::dist {

/// A failure as the outcome a rank carries through a collective (dist/outcome.hpp).
dist::Outcome outcome_of(const io::Failure& failure);

/// The runs of rank `rank` of `size`: every i < count with i % size == rank, ascending.
std::vector<std::size_t> share_of(std::size_t count, std::size_t rank, std::size_t size);

/// Collective on `comm`: `run_share(indices)` runs this rank's share and returns one result per
/// index, in their order; `write(ByteWriter&, const T&)` and `read(ByteReader&) -> T` carry a
/// result between ranks. Returns all `count` results in run order, on every rank. If run_share
/// throws on any rank, every rank throws dist::RankFailure naming the lowest failed rank with
/// its message and exit status (io/errors.hpp); on a single process the exception passes
/// unchanged and nothing is serialised.
template <class T, class RunShare, class Write, class Read>
std::vector<T> farm(dist::Communicator& comm, std::size_t count, RunShare&& run_share,
                    Write&& write, Read&& read) {
  const std::vector<std::size_t> mine = share_of(count, comm.rank(), comm.size());
  if (comm.size() == 1) return run_share(std::span<const std::size_t>(mine));
  dist::Outcome outcome;
  dist::ByteWriter out;
  try {
    const std::vector<T> results = run_share(std::span<const std::size_t>(mine));
    if (results.size() != mine.size())
      throw std::logic_error("farm: a share returned " + std::to_string(results.size()) +
                             " results for " + std::to_string(mine.size()) + " runs");
    for (const T& r : results) write(out, r);
  } catch (...) {
    outcome = outcome_of(io::failure_of(std::current_exception()));
  }
  const auto payloads = dist::gather_outcomes(comm, outcome, out.bytes());
  std::vector<T> all(count);
  for (std::size_t rank = 0; rank < payloads.size(); ++rank) {
    dist::ByteReader in(payloads[rank]);
    for (const std::size_t i : share_of(count, rank, comm.size())) all[i] = read(in);
    if (in.remaining() != 0)
      throw std::runtime_error("rank " + std::to_string(rank) + " sent more than its results");
  }
  return all;
}

}  // namespace antslam::dist
