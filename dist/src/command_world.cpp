#include "antslam/dist/command_world.hpp"

#include <stdexcept>

namespace antslam::dist {

namespace {

bool& inside_scope() {
  static bool inside = false;
  return inside;
}

}  // namespace

dist::Communicator& command_world() {
  static dist::SingleProcess single;
  return inside_scope() ? single : dist::world();
}

SingleProcessScope::SingleProcessScope() {
  if (inside_scope()) throw std::logic_error("single-process scopes do not nest");
  inside_scope() = true;
}

SingleProcessScope::~SingleProcessScope() { inside_scope() = false; }

}  // namespace antslam::dist
