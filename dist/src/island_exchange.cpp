#include "antslam/dist/island_exchange.hpp"

#include <cstdint>
#include <exception>
#include <span>
#include <utility>
#include <vector>

#include "antslam/dist/byte_stream.hpp"
#include "antslam/dist/farm.hpp"
#include "antslam/dist/outcome.hpp"
#include "antslam/io/errors.hpp"

namespace antslam::dist {

aco::Exchange island_exchange(Communicator& comm) {
  return [&comm](std::vector<aco::Offer> local, const std::exception_ptr& failure) {
    Outcome outcome;
    ByteWriter out;
    if (failure) {
      outcome = outcome_of(io::failure_of(failure));
    } else {
      out.value(static_cast<std::uint64_t>(local.size()));
      for (const aco::Offer& o : local) {
        out.value(o.best);
        out.value(o.iteration_best);
        out.value(o.stop);
        out.values(std::span<const std::uint32_t>(o.path));
      }
    }
    std::vector<aco::Offer> all;
    for (const std::vector<std::byte>& payload : gather_outcomes(comm, outcome, out.bytes())) {
      ByteReader in(payload);
      const auto count = in.value<std::uint64_t>();
      for (std::uint64_t i = 0; i < count; ++i) {
        aco::Offer o;
        o.best = in.value<double>();
        o.iteration_best = in.value<double>();
        o.stop = in.value<std::uint8_t>();
        o.path = in.values<std::uint32_t>();
        all.push_back(std::move(o));
      }
    }
    return all;
  };
}

}  // namespace antslam::dist
