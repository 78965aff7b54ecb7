// TSPLIB tours (tsp/tsplib.hpp): the first byte picks the instance size n in [3, 66], the rest is
// the file. A tour read is a permutation of 0..n-1, and writing it reads back the same.

#include <sstream>
#include <vector>

#include "antslam/tsp/tsplib.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antslam;
  if (size == 0) return 0;
  const std::size_t n = 3 + data[0] % 64;
  std::istringstream in(fuzz::text_of(data + 1, size - 1));
  std::vector<std::uint32_t> tour;
  if (!fuzz::reads([&] { tour = tsp::parse_tour(in, std::string(fuzz::kSource), n); })) return 0;
  fuzz::require(tour.size() == n, "a tour visits n nodes");
  std::vector<bool> seen(n, false);
  for (const std::uint32_t c : tour) {
    fuzz::require(c < n && !seen[c], "each node once");
    seen[c] = true;
  }
  std::stringstream written;
  tsp::write_tour(written, "fuzz", tour, "round trip");
  std::vector<std::uint32_t> back;
  fuzz::require(fuzz::reads([&] { back = tsp::parse_tour(written, "fuzz-written", n); }),
                "the writer's output reads back");
  fuzz::require(back == tour, "the same tour after a round trip");
  return 0;
}
