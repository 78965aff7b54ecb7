// The build without MPI: every run is a single process.

#include <cstdlib>

#include "antslam/dist/communicator.hpp"

namespace antslam::dist {

Communicator& world() {
  static SingleProcess single;
  return single;
}

bool built_with_mpi() { return false; }

MpiSession::MpiSession(int& /*argc*/, char**& /*argv*/) {}
MpiSession::~MpiSession() = default;

void MpiSession::abort_run(int status) { std::exit(status); }

}  // namespace antslam::dist
