#pragma once
// The QAP as an engine problem (aco::AssignmentProblem): a solution's path is the assignment,
// path[i] = the location of facility i. Its family, the engine's assignment family (pheromone on
// facility-location pairs, Stuetzle & Hoos 2000), is chosen through aco::family_of below: the
// colony itself knows nothing of assignment problems.

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>

#include "antslam/aco/assignment_family.hpp"
#include "antslam/aco/family.hpp"
#include "antslam/qap/instance.hpp"

namespace antslam::qap {

class QapProblem {
 public:
  explicit QapProblem(Instance instance) : instance_(std::move(instance)) {}

  std::size_t size() const { return instance_.size(); }
  /// The exact cost of Instance::cost (integers below 2^53 are exact doubles).
  double cost(std::span<const std::uint32_t> assignment) const {
    return static_cast<double>(instance_.cost(assignment));
  }
  const Instance& instance() const { return instance_; }

 private:
  Instance instance_;
};

}  // namespace antslam::qap

template <>
struct antslam::aco::family_of<antslam::qap::QapProblem> {
  using type = AssignmentFamily<antslam::qap::QapProblem>;
};
