// QAPLIB instances (qap/qaplib.hpp): any input is an instance or one line naming the problem,
// and an instance read back from what the writer makes has the same matrices.

#include <algorithm>
#include <istream>
#include <sstream>
#include <string>

#include "antslam/qap/qaplib.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antslam;
  std::istringstream in(fuzz::text_of(data, size));
  qap::Instance instance;
  if (!fuzz::reads([&] { instance = qap::parse_qaplib(in, std::string(fuzz::kSource)); })) return 0;
  const qap::Instance back = fuzz::written_and_read_back(
      instance, qap::write_qaplib,
      [](std::istream& text, const char* source) { return qap::parse_qaplib(text, source); });
  fuzz::require(back.size() == instance.size() &&
                    std::ranges::equal(back.flows(), instance.flows()) &&
                    std::ranges::equal(back.distances(), instance.distances()),
                "same matrices after a round trip");
  return 0;
}
