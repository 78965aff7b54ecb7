// Fragment-set JSON (slamgraph/fragment_set_io.hpp): any input is a valid set or one line naming
// the problem, and a set written reads back.

#include <sstream>

#include "antslam/slamgraph/fragment_set_io.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antslam;
  std::istringstream in(fuzz::text_of(data, size));
  slam::FragmentSet set;
  if (!fuzz::reads([&] { set = slam::read_fragment_set(in, std::string(fuzz::kSource)); }))
    return 0;
  const slam::FragmentSet back =
      fuzz::written_and_read_back(set, slam::write_fragment_set, slam::read_fragment_set);
  fuzz::require(
      back.fragments.size() == set.fragments.size() && back.closures.size() == set.closures.size(),
      "the same set after a round trip");
  return 0;
}
