#pragma once
// One function per area registers that area's classes and functions on its submodule of
// antslam._core; the Python package (python/antslam) wraps them in keyword-argument functions.

#include <pybind11/pybind11.h>

#include <string>

#include "antslam/aco/backend_kind.hpp"

namespace antslam::python {

namespace py = pybind11;

void bind_engine(py::module_& aco);          ///< engine.cpp: Parameters, Termination, Run
void bind_layered(py::module_& aco);         ///< layered_bindings.cpp: problems from tables
void bind_tsp(py::module_& tsp);             ///< tsp_bindings.cpp
void bind_slam_data(py::module_& slam);      ///< slam_data_bindings.cpp: sets and graphs
void bind_slam_optimize(py::module_& slam);  ///< slam_optimize_bindings.cpp
void bind_robust(py::module_& slam);         ///< robust_bindings.cpp: false closures
void bind_mapping(py::module_& mapping);     ///< mapping_bindings.cpp: the pipeline
void bind_eval(py::module_& eval);           ///< eval_bindings.cpp
void bind_clique(py::module_& clique);       ///< clique_bindings.cpp: maximum cliques

/// "NAME: unknown 'VALUE' (expected one of A, B, C)".
[[noreturn]] void unknown_name(const char* name, const std::string& value,
                               const std::string& expected);

/// The backend of that name (auto, serial, omp, tbb); unknown_name otherwise.
aco::BackendKind backend_from(const std::string& name);

/// A number as a repr shows it: up to 6 significant digits ("426", "0.0709", "1.5e+07").
std::string number_text(double value);

}  // namespace antslam::python
