// g2o pose graphs (slamgraph/g2o.hpp): any input is a graph or one line naming the problem; a
// graph written reads back with the same vertices and edges, and importing it as a fragment set
// gives a valid set or one line naming the problem.

#include <sstream>

#include "fuzz_support.hpp"
#include "slamgraph/g2o.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antslam;
  std::istringstream in(fuzz::text_of(data, size));
  slam::PoseGraph graph;
  if (!fuzz::reads([&] { graph = slam::read_g2o(in, std::string(fuzz::kSource)); })) return 0;
  const slam::PoseGraph back = fuzz::written_and_read_back(graph, slam::write_g2o, slam::read_g2o);
  fuzz::require(
      back.vertices.size() == graph.vertices.size() && back.edges.size() == graph.edges.size(),
      "the same graph after a round trip");
  fuzz::reads([&] {
    slam::validate(
        slam::fragment_set_from_g2o(graph, {.samples = 3, .seed = 1}, std::string(fuzz::kSource)));
  });
  return 0;
}
