// TSPLIB instances (tsp/tsplib.hpp): any input is an instance or one line naming the problem,
// and an instance read back from what the writer makes has the same distances.

#include <sstream>

#include "antslam/tsp/tsplib.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antslam;
  std::istringstream in(fuzz::text_of(data, size));
  tsp::Instance instance;
  if (!fuzz::reads([&] { instance = tsp::parse_instance(in, std::string(fuzz::kSource)); }))
    return 0;
  const tsp::Instance back =
      fuzz::written_and_read_back(instance, tsp::write_instance, tsp::parse_instance);
  fuzz::require(back.size() == instance.size(), "same size after a round trip");
  const auto n = static_cast<std::uint32_t>(instance.size());
  for (std::uint32_t i = 0; i < n && i < 64; ++i)
    fuzz::require(back.distance(i, (i + 1) % n) == instance.distance(i, (i + 1) % n),
                  "same distances after a round trip");
  return 0;
}
