#include "antslam/dist/outcome.hpp"

namespace antslam::dist {

RankFailure::RankFailure(std::size_t rank, const Outcome& outcome)
    : std::runtime_error("rank " + std::to_string(rank) + ": " + outcome.message),
      rank_(rank),
      status_(outcome.status),
      cause_(outcome.message) {}

void write(ByteWriter& out, const Outcome& outcome) {
  out.value(static_cast<std::uint8_t>(outcome.failed ? 1 : 0));
  out.value(static_cast<std::int32_t>(outcome.status));
  out.text(outcome.message);
}

Outcome read_outcome(ByteReader& in) {
  Outcome outcome;
  outcome.failed = in.value<std::uint8_t>() != 0;
  outcome.status = in.value<std::int32_t>();
  outcome.message = in.text();
  return outcome;
}

std::vector<std::vector<std::byte>> gather_outcomes(Communicator& comm, const Outcome& mine,
                                                    std::span<const std::byte> payload) {
  ByteWriter out;
  write(out, mine);
  if (!mine.failed) out.values(payload);
  auto received = comm.all_gather(out.bytes());
  std::vector<std::vector<std::byte>> payloads(received.size());
  for (std::size_t r = 0; r < received.size(); ++r) {
    ByteReader in(received[r]);
    const Outcome outcome = read_outcome(in);
    if (outcome.failed) throw RankFailure(r, outcome);
    payloads[r] = in.values<std::byte>();
  }
  return payloads;
}

}  // namespace antslam::dist
