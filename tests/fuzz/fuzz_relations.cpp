// Relations files (eval/relations.hpp): any input is a list of relations or one line naming the
// problem; every relation read is finite and within the limits.

#include <cmath>
#include <sstream>

#include "antslam/eval/relations.hpp"
#include "antslam/slamgraph/trajectory.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antslam;
  std::istringstream in(fuzz::text_of(data, size));
  std::vector<eval::Relation> relations;
  if (!fuzz::reads([&] { relations = eval::read_relations(in, std::string(fuzz::kSource)); }))
    return 0;
  for (const eval::Relation& r : relations)
    fuzz::require(std::abs(r.stamp1) <= slam::kMaxTimestamp &&
                      std::abs(r.motion.x) <= slam::kMaxCoordinate && std::isfinite(r.motion.theta),
                  "relations within the limits");
  return 0;
}
