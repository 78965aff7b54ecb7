// A deliberate race in the body of a parallel loop: ThreadSanitizer must report it on the OpenMP
// and the TBB backend (CTest expects the report), which shows that the TSan run of the parallel
// tests sees antslam's own code through both threading runtimes.
#include <cstdio>
#include <string_view>

#include "antslam/aco/backend_omp.hpp"
#include "antslam/aco/backend_tbb.hpp"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  long sum = 0;
  const auto racy = [&](std::size_t i) {
    volatile double work = 0.0;  // long enough that both threads take iterations
    for (int k = 0; k < 20000; ++k) work = work + k;
    sum += static_cast<long>(i);  // unsynchronised read-modify-write from every thread
  };
  if (std::string_view(argv[1]) == "omp") {
    antslam::aco::OmpBackend(2).for_each(200, racy);
  } else {
    antslam::aco::TbbBackend(2).for_each(200, racy);
  }
  std::printf("%ld\n", sum);
  return 0;
}
