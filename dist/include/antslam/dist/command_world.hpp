#pragma once
// The processes a command runs on: every rank of the run (dist::world()), except while
// `antslam batch` runs one of its jobs, which runs on its rank alone. Commands farm their
// independent runs over it (dist/farm.hpp), and only its root writes outputs and prints results.

#include "antslam/dist/communicator.hpp"

namespace antslam::dist {

/// dist::world(), or a single process inside a SingleProcessScope.
dist::Communicator& command_world();

/// For its life, command_world() is a single process (this rank alone runs, writes and prints).
/// Scopes do not nest: a second one throws std::logic_error.
class SingleProcessScope {
 public:
  SingleProcessScope();
  ~SingleProcessScope();
  SingleProcessScope(const SingleProcessScope&) = delete;
  SingleProcessScope& operator=(const SingleProcessScope&) = delete;
};

}  // namespace antslam::dist
