// antslam._core: the compiled part of the Python package.

#include <pybind11/pybind11.h>

#include <exception>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>

#include "antslam/io/errors.hpp"
#include "antslam/version.hpp"
#include "bindings.hpp"
#include "interrupt.hpp"

namespace antslam::python {

void unknown_name(const char* name, const std::string& value, const std::string& expected) {
  throw std::invalid_argument(std::string(name) + ": unknown '" + value + "' (expected one of " +
                              expected + ")");
}

aco::BackendKind backend_from(const std::string& name) {
  const auto kind = aco::parse_backend(name);
  if (!kind) unknown_name("backend", name, aco::backend_names());
  return *kind;
}

std::string number_text(double value) {
  std::ostringstream out;
  out << std::setprecision(6) << value;
  return out.str();
}

namespace {

/// The library's exceptions as pybind11 maps them (ValueError, IndexError, OverflowError,
/// RuntimeError), but with the antslam program's one-line message: a message quoting bytes of a
/// file that are not UTF-8 would otherwise be lost (Python raised RuntimeError('')).
void translate_library_errors(std::exception_ptr error) {
  const auto raise = [](PyObject* type, const std::exception& e) {
    PyErr_SetString(type, io::one_line(e.what()).c_str());
  };
  try {
    if (error) std::rethrow_exception(error);
  } catch (const py::builtin_exception& e) {
    e.set_error();  // pybind11's own (value_error, type_error, ...), unchanged
  } catch (const std::invalid_argument& e) {
    raise(PyExc_ValueError, e);
  } catch (const std::domain_error& e) {
    raise(PyExc_ValueError, e);
  } catch (const std::length_error& e) {
    raise(PyExc_ValueError, e);
  } catch (const std::out_of_range& e) {
    raise(PyExc_IndexError, e);
  } catch (const std::range_error& e) {
    raise(PyExc_ValueError, e);
  } catch (const std::overflow_error& e) {
    raise(PyExc_OverflowError, e);
  } catch (const std::runtime_error& e) {
    raise(PyExc_RuntimeError, e);
  }
}

}  // namespace

}  // namespace antslam::python

PYBIND11_MODULE(_core, m) {
  using namespace antslam::python;
  py::register_exception_translator(translate_library_errors);
  m.doc() = "antslam: ant colony optimization for SLAM map optimization and the TSP";
  m.attr("__version__") = antslam::kVersion;
  bind_interrupted(m);
  py::module_ aco = m.def_submodule("aco", "The colony engine: parameters and layered problems");
  bind_engine(aco);
  bind_layered(aco);
  py::module_ tsp = m.def_submodule("tsp", "TSPLIB instances and the TSP solver");
  bind_tsp(tsp);
  py::module_ slam = m.def_submodule("slam", "Fragment sets, pose graphs and their optimizers");
  bind_slam_data(slam);
  bind_slam_optimize(slam);
  py::module_ clique = m.def_submodule("clique", "Maximum cliques: the ants, branch and bound");
  bind_clique(clique);  // before the robust back ends, whose settings hold the ants' settings
  bind_robust(slam);
  py::module_ mapping = m.def_submodule("mapping", "The AntSLAM pipeline on a laser log");
  bind_mapping(mapping);
  py::module_ eval = m.def_submodule("eval", "Trajectory evaluation: ATE, RPE, relations");
  bind_eval(eval);
}
