#pragma once
// How a rank's share of a collective step ended, carried through the collective itself so that
// a failure on one rank stops every rank at the same point (no rank is left waiting in a
// collective that the failed one never reaches) and the run ends with one line naming the rank.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "antslam/dist/byte_stream.hpp"
#include "antslam/dist/communicator.hpp"

namespace antslam::dist {

/// A rank's share ended: ok, or failed with an exit status and a one-line message.
struct Outcome {
  bool failed = false;
  int status = 0;       ///< the exit status the failure calls for (0 when ok)
  std::string message;  ///< one line (empty when ok)
};

/// Thrown on every rank when some rank failed: the lowest failed rank, its status and message.
class RankFailure : public std::runtime_error {
 public:
  RankFailure(std::size_t rank, const Outcome& outcome);
  std::size_t rank() const { return rank_; }
  int status() const { return status_; }
  /// The failed rank's own message, without the rank.
  const std::string& cause() const { return cause_; }

 private:
  std::size_t rank_;
  int status_;
  std::string cause_;
};

void write(ByteWriter& out, const Outcome& outcome);
Outcome read_outcome(ByteReader& in);

/// Collective: every rank's outcome, then the rank's payload bytes (empty for a failed rank);
/// throws RankFailure on every rank if any rank failed, else returns every rank's payload in
/// rank order.
std::vector<std::vector<std::byte>> gather_outcomes(Communicator& comm, const Outcome& mine,
                                                    std::span<const std::byte> payload = {});

}  // namespace antslam::dist
