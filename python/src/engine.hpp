#pragma once
// The engine's pieces every binding shares: its parameters and stop criteria as Python classes,
// the per-iteration report handed to a Python observer, and a run's result.

#include <pybind11/pybind11.h>

#include <cstdint>
#include <vector>

#include "antslam/aco/colony.hpp"
#include "antslam/aco/variants.hpp"
#include "bindings.hpp"
#include "interrupt.hpp"

namespace antslam::python {

/// A copy of aco::IterationReport that Python may keep.
struct IterationInfo {
  std::uint64_t iteration = 0;      ///< 1-based
  double elapsed_s = 0.0;           ///< seconds since the run started
  double iteration_best = 0.0;      ///< best cost of the iteration
  double global_best = 0.0;         ///< best cost so far
  bool improved = false;            ///< the iteration found a new best
  std::vector<std::uint32_t> best;  ///< the best path so far
};

/// The colony observer that hands each report to `observer` on the Python thread; an empty
/// observer for None. It refers to `observer`, which must outlive the run.
aco::Observer colony_observer(const py::object& observer, PythonThread& python);

}  // namespace antslam::python
