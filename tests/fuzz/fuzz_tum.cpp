// TUM trajectories (slamgraph/trajectory.hpp): any input is a trajectory or one line naming the
// problem; what is read can be written, and reads back the same to the writer's precision.

#include <cmath>
#include <sstream>

#include "antslam/slamgraph/trajectory.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antslam;
  std::istringstream in(fuzz::text_of(data, size));
  slam::Trajectory trajectory;
  if (!fuzz::reads([&] { trajectory = slam::read_tum(in, std::string(fuzz::kSource)); })) return 0;
  const slam::Trajectory back =
      fuzz::written_and_read_back(trajectory, slam::write_tum, slam::read_tum);
  fuzz::require(back.size() == trajectory.size(), "the same poses after a round trip");
  for (std::size_t i = 0; i < back.size(); ++i)
    fuzz::require(std::abs(back[i].pose.x - trajectory[i].pose.x) <=
                      1e-8 * (1.0 + std::abs(trajectory[i].pose.x)),
                  "x survives the round trip");
  return 0;
}
