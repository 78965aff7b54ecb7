#pragma once
// The parallel backends by name: the one place where "serial", "omp", "tbb" or "auto" becomes a
// backend. The factory that builds one (backend_factory.hpp) needs the OpenMP and TBB runtimes;
// this header needs nothing, so that settings can name a backend without linking either.

#include <array>
#include <cstddef>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace antslam::aco {

enum class BackendKind {
  automatic,  ///< serial on one thread, TBB on more (OpenMP spin-waits when cores are shared)
  serial,     ///< the calling thread only
  omp,        ///< OpenMP parallel for
  tbb,        ///< oneTBB parallel_for in a task arena of the requested size
};

struct BackendInfo {
  BackendKind kind;
  std::string_view name;     ///< the name options and files use
  std::string_view summary;  ///< one line for help texts
};

inline constexpr std::array<BackendInfo, 4> kBackends{{
    {BackendKind::automatic, "auto", "serial on 1 thread, else tbb"},
    {BackendKind::serial, "serial", "the calling thread only"},
    {BackendKind::omp, "omp", "OpenMP (on a shared machine set OMP_WAIT_POLICY=passive)"},
    {BackendKind::tbb, "tbb", "oneTBB task arena"},
}};

constexpr std::string_view to_string(BackendKind kind) {
  for (const BackendInfo& b : kBackends)
    if (b.kind == kind) return b.name;
  return "?";
}

/// GoogleTest and logs print the name.
inline void PrintTo(BackendKind kind, std::ostream* os) { *os << to_string(kind); }

constexpr std::optional<BackendKind> parse_backend(std::string_view name) {
  for (const BackendInfo& b : kBackends)
    if (b.name == name) return b.kind;
  return std::nullopt;
}

/// "auto, serial, omp, tbb".
inline std::string backend_names() {
  std::string names;
  for (const BackendInfo& b : kBackends) names += (names.empty() ? "" : ", ") + std::string(b.name);
  return names;
}

/// The backend `kind` stands for with `threads` threads (0 = all cores): automatic becomes
/// serial on one thread and tbb otherwise. Throws std::invalid_argument for serial on more than
/// one thread.
inline BackendKind resolve(BackendKind kind, std::size_t threads) {
  if (kind == BackendKind::automatic) return threads == 1 ? BackendKind::serial : BackendKind::tbb;
  if (kind == BackendKind::serial && threads != 1)
    throw std::invalid_argument(
        "backend serial runs on exactly 1 thread, not " +
        (threads == 0 ? std::string("all cores") : std::to_string(threads)));
  return kind;
}

}  // namespace antslam::aco
