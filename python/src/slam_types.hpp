#pragma once
// The slam types the Python classes wrap: a pose graph with the name of the file it came from
// (for messages).

#include <string>

#include "antslam/slamgraph/g2o.hpp"

namespace antslam::python {

struct NamedGraph {
  slam::PoseGraph graph;
  std::string name;  ///< the file it was read from, or a name the user gave
};

}  // namespace antslam::python
