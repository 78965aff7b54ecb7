#pragma once
// Builds the backend a BackendKind names. Link antslam::aco_parallel (OpenMP and TBB).
//   with_backend(kind, threads, f)  calls f(backend) with the concrete backend type, so the
//                                   colony's per-ant loop stays static;
//   make_backend(kind, threads)     the same backend type-erased, for run-time plumbing.

#include <cstddef>
#include <utility>

#include "antslam/aco/backend.hpp"
#include "antslam/aco/backend_kind.hpp"
#include "antslam/aco/backend_omp.hpp"
#include "antslam/aco/backend_tbb.hpp"

namespace antslam::aco {

/// threads = 0: all cores. Throws std::invalid_argument for serial on more than one thread.
template <class F>
decltype(auto) with_backend(BackendKind kind, std::size_t threads, F&& f) {
  switch (resolve(kind, threads)) {
    case BackendKind::omp:
      return std::forward<F>(f)(OmpBackend(threads));
    case BackendKind::tbb:
      return std::forward<F>(f)(TbbBackend(threads));
    case BackendKind::automatic:
    case BackendKind::serial:
      break;
  }
  return std::forward<F>(f)(SerialBackend{});
}

inline AnyBackend make_backend(BackendKind kind, std::size_t threads) {
  return with_backend(kind, threads, [](auto backend) { return AnyBackend(std::move(backend)); });
}

}  // namespace antslam::aco
