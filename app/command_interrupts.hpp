#pragma once
// A command that keeps what it found on Ctrl-C (io/interrupts.hpp) holds one of these while it
// works: on one process the first interrupt requests a stop on token(); under mpirun nothing is
// armed (the launcher ends the ranks; nothing is kept), not even for a batch job that runs on
// its rank alone.

#include <optional>
#include <stop_token>

#include "antslam/dist/communicator.hpp"
#include "antslam/io/interrupts.hpp"

namespace antslam::cli {

class CommandInterrupts {
 public:
  CommandInterrupts() {
    if (dist::world().size() == 1) stop_.emplace();
  }
  /// What the command's runs honour; never stopped under mpirun.
  std::stop_token token() const { return stop_ ? stop_->token() : std::stop_token{}; }
  /// The signal that requested the stop; 0 while none did.
  int signal() const { return stop_ ? stop_->signal() : 0; }

 private:
  std::optional<io::StopOnInterrupt> stop_;
};

}  // namespace antslam::cli
