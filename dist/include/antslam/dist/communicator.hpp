#pragma once
// The processes of one run and the one collective operation the distributed features need.
// A run started by an MPI launcher (mpirun, mpiexec, srun) in a build with MPI has one rank per
// process; every other run is a single process, rank 0 of 1, and behaves exactly as without
// MPI. Collectives are called by every rank in the same order (the MPI rule); code that may
// fail on one rank only carries its failure through them (collective.hpp) instead of leaving
// the others waiting.

#include <cstddef>
#include <span>
#include <vector>

namespace antslam::dist {

class Communicator {
 public:
  virtual ~Communicator() = default;

  /// This process's index, 0 <= rank() < size().
  virtual std::size_t rank() const = 0;
  /// How many processes run.
  virtual std::size_t size() const = 0;

  /// Every rank's bytes, in rank order, on every rank (collective; the ranks may contribute
  /// different lengths).
  virtual std::vector<std::vector<std::byte>> all_gather(std::span<const std::byte> mine) = 0;

  /// Whether this rank writes outputs and prints results (rank 0).
  bool is_root() const { return rank() == 0; }
};

/// One process: rank 0 of 1; all_gather returns its own bytes.
class SingleProcess final : public Communicator {
 public:
  std::size_t rank() const override { return 0; }
  std::size_t size() const override { return 1; }
  std::vector<std::vector<std::byte>> all_gather(std::span<const std::byte> mine) override {
    return {std::vector<std::byte>(mine.begin(), mine.end())};
  }
};

/// The run's communicator: all ranks of MPI_COMM_WORLD after an MpiSession started under an MPI
/// launcher, a SingleProcess otherwise.
Communicator& world();

/// Whether this build can run over MPI (ANTSLAM_WITH_MPI).
bool built_with_mpi();

/// Initialises MPI for the life of the object when the process was started by an MPI launcher
/// (and the build has MPI); otherwise does nothing, so a plain run never touches MPI.
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  /// Ends the whole run at once with this exit status (MPI_Abort when MPI runs, std::exit
  /// otherwise): for a failure that the other ranks cannot be told about through a collective.
  [[noreturn]] static void abort_run(int status);
};

}  // namespace antslam::dist
