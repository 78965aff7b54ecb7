// antslam.aco: a layered-choice problem from tables and a Python term, run by any variant.

#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "antslam/aco/backend_factory.hpp"
#include "arrays.hpp"
#include "bindings.hpp"
#include "engine.hpp"
#include "table_problem.hpp"

namespace antslam::python {

namespace {

std::vector<std::vector<double>> rows(const std::vector<DoubleArray>& arrays) {
  std::vector<std::vector<double>> out;
  for (const DoubleArray& a : arrays) out.emplace_back(a.data(), a.data() + a.size());
  return out;
}

/// The user's term, called on the ants' threads with the GIL held; an exception or a value that
/// is not a finite number >= 0 fails the call (and the ant gets an infinite cost meanwhile).
TableProblem::Term python_term(const py::object& term, PythonThread& python) {
  if (term.is_none()) return {};
  return [&term, &python](std::span<const std::uint32_t> choice) {
    const py::gil_scoped_acquire gil;
    try {
      const py::object value = term(index_array(choice));
      const double v = py::float_(value).cast<double>();
      if (std::isfinite(v) && v >= 0.0) return v;
      PyErr_SetString(PyExc_ValueError, ("term: returned " + std::string(py::repr(value)) +
                                         ", expected a finite number >= 0")
                                            .c_str());
      throw py::error_already_set();
    } catch (py::error_already_set& e) {
      python.fail(std::move(e));
    }
    return std::numeric_limits<double>::infinity();
  };
}

aco::RunResult solve_layered(const std::vector<DoubleArray>& costs,
                             const std::vector<DoubleArray>& pairwise,
                             const std::vector<DoubleArray>& heuristic, const py::object& term,
                             const aco::Parameters& parameters, const aco::Termination& termination,
                             const std::string& backend, std::size_t threads,
                             const py::object& observer) {
  const aco::BackendKind kind = aco::resolve(backend_from(backend), threads);
  std::vector<std::vector<double>> unary = rows(costs), pairs = rows(pairwise),
                                   eta = rows(heuristic);
  return run_interruptible([&](PythonThread& python) {
    const TableProblem problem(std::move(unary), std::move(pairs), std::move(eta),
                               python_term(term, python));
    aco::Termination t = termination;
    t.stop = python.stop_token();
    const aco::Observer observe = colony_observer(observer, python);
    return aco::with_backend(kind, threads, [&](auto b) {
      return aco::solve(problem, parameters, t, b, aco::NoLocalSearch{}, observe);
    });
  });
}

}  // namespace

void bind_layered(py::module_& m) {
  m.def("solve_layered", &solve_layered, py::arg("costs"), py::arg("pairwise"),
        py::arg("heuristic"), py::arg("term"), py::arg("parameters"), py::arg("termination"),
        py::arg("backend"), py::arg("threads"), py::arg("observer"),
        "A layered-choice problem from tables (table_problem.hpp) by any variant; see "
        "antslam.aco.solve for the arguments.");
  m.def("backend_names", [] { return aco::backend_names(); });
  m.def("variant_names", [] { return aco::variant_names(); });
}

}  // namespace antslam::python
