// The build with MPI: MPI_COMM_WORLD when an MPI launcher started the process.

#include <mpi.h>

#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "antslam/dist/communicator.hpp"

namespace antslam::dist {
namespace {

/// MPI_COMM_WORLD. MPI runs on the main thread only (MPI_THREAD_FUNNELED): the ants' threads
/// never call it.
class MpiWorld final : public Communicator {
 public:
  MpiWorld() {
    int rank = 0;
    int size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    rank_ = static_cast<std::size_t>(rank);
    size_ = static_cast<std::size_t>(size);
  }
  std::size_t rank() const override { return rank_; }
  std::size_t size() const override { return size_; }

  std::vector<std::vector<std::byte>> all_gather(std::span<const std::byte> mine) override {
    constexpr auto kMaxBytes = static_cast<std::size_t>(std::numeric_limits<int>::max());
    std::uint64_t length = mine.size();
    std::vector<std::uint64_t> lengths(size_);
    MPI_Allgather(&length, 1, MPI_UINT64_T, lengths.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD);
    std::vector<int> counts(size_);
    std::vector<int> displacements(size_);
    std::size_t total = 0;
    for (std::size_t r = 0; r < size_; ++r) {
      if (lengths[r] > kMaxBytes || total + lengths[r] > kMaxBytes)
        throw std::runtime_error("MPI: rank " + std::to_string(r) + " sends " +
                                 std::to_string(lengths[r]) +
                                 " bytes, more than one exchange carries (2 GiB in all)");
      counts[r] = static_cast<int>(lengths[r]);
      displacements[r] = static_cast<int>(total);
      total += lengths[r];
    }
    std::vector<std::byte> all(total);
    MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), MPI_BYTE, all.data(), counts.data(),
                   displacements.data(), MPI_BYTE, MPI_COMM_WORLD);
    std::vector<std::vector<std::byte>> result(size_);
    for (std::size_t r = 0; r < size_; ++r) {
      const auto* first = all.data() + displacements[r];
      result[r].assign(first, first + counts[r]);
    }
    return result;
  }

 private:
  std::size_t rank_ = 0;
  std::size_t size_ = 1;
};

std::unique_ptr<MpiWorld>& mpi_world() {
  static std::unique_ptr<MpiWorld> world;
  return world;
}

/// Open MPI's mpirun, PMIx launchers (Slurm's srun --mpi=pmix) and PMI-1/2 launchers (MPICH's
/// mpiexec, srun --mpi=pmi2) each set one of these in every process they start.
bool started_by_mpi_launcher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

}  // namespace

Communicator& world() {
  if (auto& mpi = mpi_world()) return *mpi;
  static SingleProcess single;
  return single;
}

bool built_with_mpi() { return true; }

MpiSession::MpiSession(int& argc, char**& argv) {
  if (!started_by_mpi_launcher()) return;
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  mpi_world() = std::make_unique<MpiWorld>();
}

MpiSession::~MpiSession() {
  if (!mpi_world()) return;
  mpi_world().reset();
  MPI_Finalize();
}

void MpiSession::abort_run(int status) {
  if (mpi_world()) MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status);
}

}  // namespace antslam::dist
