#include "antslam/dist/farm.hpp"

namespace antslam::dist {

dist::Outcome outcome_of(const io::Failure& failure) {
  return {true, static_cast<int>(failure.status), failure.message};
}

std::vector<std::size_t> share_of(std::size_t count, std::size_t rank, std::size_t size) {
  if (size == 0 || rank >= size)
    throw std::invalid_argument("share_of: rank " + std::to_string(rank) + " of " +
                                std::to_string(size));
  std::vector<std::size_t> share;
  for (std::size_t i = rank; i < count; i += size) share.push_back(i);
  return share;
}

}  // namespace antslam::dist
