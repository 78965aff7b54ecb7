// g2o and TORO pose graphs (slamgraph/g2o.hpp): any input is a graph or one line naming the
// problem; a graph written as g2o and as TORO reads back with the same vertices and edges (the
// two read-backs alike, number for number: TORO's order of the information entries is undone),
// and importing it as a fragment set gives a valid set or one line naming the problem.

#include <sstream>

#include "antslam/slamgraph/g2o.hpp"
#include "fuzz_support.hpp"

namespace {

bool same_pose(const antslam::slam::Pose2& a, const antslam::slam::Pose2& b) {
  return a.x == b.x && a.y == b.y && a.theta == b.theta;
}

bool same_graph(const antslam::slam::PoseGraph& a, const antslam::slam::PoseGraph& b) {
  if (a.vertices.size() != b.vertices.size() || a.edges.size() != b.edges.size() ||
      a.fixed != b.fixed)
    return false;
  for (std::size_t i = 0; i < a.vertices.size(); ++i)
    if (!same_pose(a.vertices[i], b.vertices[i])) return false;
  for (std::size_t e = 0; e < a.edges.size(); ++e) {
    const antslam::slam::PoseGraphEdge& x = a.edges[e];
    const antslam::slam::PoseGraphEdge& y = b.edges[e];
    if (x.from != y.from || x.to != y.to || !same_pose(x.measurement, y.measurement) ||
        x.information != y.information)
      return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antslam;
  std::istringstream in(fuzz::text_of(data, size));
  slam::PoseGraph graph;
  if (!fuzz::reads([&] { graph = slam::read_g2o(in, std::string(fuzz::kSource)); })) return 0;
  const slam::PoseGraph back = fuzz::written_and_read_back(graph, slam::write_g2o, slam::read_g2o);
  fuzz::require(
      back.vertices.size() == graph.vertices.size() && back.edges.size() == graph.edges.size(),
      "the same graph after a round trip");
  const slam::PoseGraph toro = fuzz::written_and_read_back(graph, slam::write_toro, slam::read_g2o);
  fuzz::require(same_graph(toro, back), "the same graph written as TORO and as g2o");
  fuzz::reads([&] {
    slam::validate(
        slam::fragment_set_from_g2o(graph, {.samples = 3, .seed = 1}, std::string(fuzz::kSource)));
  });
  return 0;
}
