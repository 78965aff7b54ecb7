// antslam.tsp: TSPLIB instances and tours, and the solver with any variant, local search and
// backend (tsp/solver.hpp).

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "antslam/io/atomic_file.hpp"
#include "antslam/tsp/generator.hpp"
#include "antslam/tsp/instance.hpp"
#include "antslam/tsp/optima.hpp"
#include "antslam/tsp/solver.hpp"
#include "antslam/tsp/tsplib.hpp"
#include "arrays.hpp"
#include "bindings.hpp"
#include "engine.hpp"
#include "pickling.hpp"

namespace antslam::python {

namespace {

/// A tour of the instance from Python: a permutation of 0..n-1.
std::vector<std::uint32_t> tour_of(const tsp::Instance& instance, const py::object& array) {
  std::vector<std::uint32_t> tour = indices_from(array, "tour");
  std::vector<bool> seen(instance.size(), false);
  for (const std::uint32_t city : tour) {
    if (city >= instance.size() || seen[city])
      throw std::invalid_argument("tour: expected a permutation of 0.." +
                                  std::to_string(instance.size() - 1));
    seen[city] = true;
  }
  if (tour.size() != instance.size())
    throw std::invalid_argument("tour: has " + std::to_string(tour.size()) + " cities, the " +
                                "instance " + std::to_string(instance.size()));
  return tour;
}

aco::RunResult solve(const tsp::Instance& instance, const tsp::SolverSettings& settings,
                     const tsp::ProblemSettings& problem_settings,
                     const aco::Termination& termination, const py::object& observer,
                     std::size_t colonies, std::uint64_t exchange_every,
                     const std::string& topology) {
  aco::resolve(settings.backend, settings.threads);  // serial on several threads fails here
  const std::optional<aco::Topology> kind = aco::parse_topology(topology);
  if (!kind) unknown_name("topology", topology, "ring, full");
  if (colonies == 0) throw std::invalid_argument("colonies: must be >= 1");
  const aco::IslandSettings islands{
      .colonies = colonies, .exchange_every = exchange_every, .topology = *kind};
  return run_interruptible([&](PythonThread& python) {
    const tsp::TspProblem problem(instance, problem_settings);
    aco::Termination t = termination;
    t.stop = python.stop_token();
    const aco::Observer each = colony_observer(observer, python);
    if (colonies == 1) return tsp::solve(problem, settings, t, each);
    return tsp::solve_islands(problem, settings, t, islands, aco::in_process_exchange,
                              [&](const aco::IslandReport& r) {
                                if (each) each(r.run);
                              })
        .run;
  });
}

/// An instance from an (n, 2) array of city coordinates under a TSPLIB distance.
tsp::Instance from_coordinates(const DoubleArray& coords, const std::string& edge_weight_type,
                               const std::string& name) {
  if (coords.ndim() != 2 || coords.shape(1) != 2)
    throw std::invalid_argument("Instance: coords: expected an (n, 2) array of (x, y)");
  const std::optional<tsp::EdgeWeightType> type = tsp::parse_edge_weight_type(edge_weight_type);
  if (!type || *type == tsp::EdgeWeightType::explicit_matrix)
    throw std::invalid_argument("Instance: edge_weight_type '" + edge_weight_type +
                                "' is not one of EUC_2D, CEIL_2D, ATT, GEO (a matrix: "
                                "Instance.from_matrix)");
  const auto v = coords.unchecked<2>();
  std::vector<tsp::Point> points(static_cast<std::size_t>(coords.shape(0)));
  for (py::ssize_t k = 0; k < coords.shape(0); ++k)
    points[static_cast<std::size_t>(k)] = {v(k, 0), v(k, 1)};
  return tsp::Instance(name, *type, std::move(points));
}

/// An EXPLICIT instance from a symmetric (n, n) array of integer distances.
tsp::Instance from_matrix(const DoubleArray& matrix, const std::string& name) {
  if (matrix.ndim() != 2 || matrix.shape(0) != matrix.shape(1))
    throw std::invalid_argument("Instance.from_matrix: expected an (n, n) array of distances");
  const auto v = matrix.unchecked<2>();
  const auto n = static_cast<std::size_t>(matrix.shape(0));
  std::vector<std::int32_t> weights;
  weights.reserve(n * n);
  for (py::ssize_t i = 0; i < matrix.shape(0); ++i)
    for (py::ssize_t j = 0; j < matrix.shape(1); ++j) {
      const double d = v(i, j);
      if (!(d >= 0.0 && d <= std::numeric_limits<std::int32_t>::max() && std::floor(d) == d)) {
        std::ostringstream what;
        what << "Instance.from_matrix: entry (" << i << ", " << j << ") is " << d
             << ", not a whole number in [0, 2^31)";
        throw std::invalid_argument(what.str());
      }
      weights.push_back(static_cast<std::int32_t>(d));
    }
  return tsp::Instance(name, n, std::move(weights));
}

}  // namespace

void bind_tsp(py::module_& m) {
  py::class_<tsp::Instance>(m, "Instance", "A symmetric TSPLIB instance (tsp/instance.hpp)")
      .def(py::init(&from_coordinates), py::arg("coords"), py::kw_only(),
           py::arg("edge_weight_type") = "EUC_2D", py::arg("name") = "python",
           "An instance from an (n, 2) array of city coordinates; distances by the TSPLIB rule "
           "of edge_weight_type (EUC_2D: Euclidean, rounded to the nearest integer)")
      .def_static("from_matrix", &from_matrix, py::arg("matrix"), py::kw_only(),
                  py::arg("name") = "python",
                  "An EXPLICIT instance from a symmetric (n, n) array of whole distances >= 0")
      .def_property_readonly("name", &tsp::Instance::name)
      .def_property_readonly("size", &tsp::Instance::size)
      .def("__len__", &tsp::Instance::size)
      .def_property_readonly(
          "edge_weight_type",
          [](const tsp::Instance& i) { return std::string(tsp::to_string(i.type())); })
      .def_readonly("comment", &tsp::Instance::comment)
      .def_property_readonly(
          "coords",
          [](const tsp::Instance& i) {
            py::array_t<double> out({static_cast<py::ssize_t>(i.coords().size()), py::ssize_t{2}});
            auto v = out.mutable_unchecked<2>();
            for (std::size_t k = 0; k < i.coords().size(); ++k) {
              v(static_cast<py::ssize_t>(k), 0) = i.coords()[k].x;
              v(static_cast<py::ssize_t>(k), 1) = i.coords()[k].y;
            }
            return out;
          })
      .def(
          "distance",
          [](const tsp::Instance& i, std::uint32_t a, std::uint32_t b) {
            if (a >= i.size() || b >= i.size())
              throw py::index_error("distance: city out of range 0.." +
                                    std::to_string(i.size() - 1));
            return i.distance(a, b);
          },
          py::arg("i"), py::arg("j"), "TSPLIB distance between cities i and j (0-based)")
      .def(
          "tour_length",
          [](const tsp::Instance& i, const py::object& tour) {
            return i.tour_length(tour_of(i, tour));
          },
          py::arg("tour"), "Length of the closed tour (a permutation of 0..n-1)")
      .def(
          "read_tour",
          [](const tsp::Instance& i, const std::filesystem::path& path) {
            return index_array(tsp::read_tour(path, i.size()));
          },
          py::arg("path"), "A TSPLIB .tour file of this instance, 0-based")
      .def(
          "write_tour",
          [](const tsp::Instance& i, const std::filesystem::path& path, const py::object& tour,
             const std::string& comment) {
            const std::vector<std::uint32_t> t = tour_of(i, tour);
            io::write_atomically(path, [&](std::ostream& out) {
              tsp::write_tour(out, i.name() + ".tour", t, comment);
            });
          },
          py::arg("path"), py::arg("tour"), py::arg("comment") = "",
          "Writes the tour as a TSPLIB .tour file (atomically)")
      .def(
          "save",
          [](const tsp::Instance& i, const std::filesystem::path& path) {
            io::write_atomically(path, [&](std::ostream& out) { tsp::write_instance(out, i); });
          },
          py::arg("path"), "Writes the instance as a TSPLIB file (atomically)")
      .def(py::pickle(
          [](const tsp::Instance& i) {
            return py::make_tuple(kPickleVersion,
                                  text_of([&](std::ostream& out) { tsp::write_instance(out, i); }));
          },
          [](const py::tuple& state) {
            check_pickle_state(state, 2, "antslam.tsp.Instance");
            std::istringstream in = text_in(state);
            return tsp::parse_instance(in, "pickled antslam.tsp.Instance");
          }))
      .def("__repr__", [](const tsp::Instance& i) {
        return "<antslam.tsp.Instance " + i.name() + ", " + std::to_string(i.size()) + " cities, " +
               std::string(tsp::to_string(i.type())) + ">";
      });

  m.def(
      "read", [](const std::filesystem::path& path) { return tsp::read_instance(path); },
      py::arg("path"), "Reads a TSPLIB instance (.tsp)");
  m.def("generate", &tsp::random_uniform_instance, py::arg("cities"), py::arg("seed"),
        py::arg("side") = 1.0e6, "Random uniform EUC_2D instance (tsp/generator.hpp)");
  m.def("known_optimum", &tsp::known_optimum, py::arg("path"),
        "The optimum of a shipped instance (optima.csv beside it), or None");

  py::class_<tsp::ProblemSettings>(m, "ProblemSettings")
      .def(py::init<>())
      .def_readwrite("candidates", &tsp::ProblemSettings::candidates)
      .def_readwrite("ls_neighbours", &tsp::ProblemSettings::ls_neighbours)
      .def_readwrite("matrix_limit", &tsp::ProblemSettings::matrix_limit);

  py::class_<tsp::SolverSettings>(m, "SolverSettings")
      .def(py::init<>())
      .def_readwrite("aco", &tsp::SolverSettings::aco)
      .def_readwrite("focused_edges", &tsp::SolverSettings::focused_edges)
      .def_readwrite("hybrid_deposit", &tsp::SolverSettings::hybrid_deposit)
      .def_readwrite("threads", &tsp::SolverSettings::threads)
      .def_property(
          "local_search",
          [](const tsp::SolverSettings& s) {
            return std::string(tsp::to_string(s.local_search.kind));
          },
          [](tsp::SolverSettings& s, const std::string& name) {
            const auto kind = tsp::parse_local_search(name);
            if (!kind) unknown_name("local_search", name, "none, 2opt, 2.5opt, 3opt");
            s.local_search.kind = *kind;
          })
      .def_property(
          "ls_neighbours", [](const tsp::SolverSettings& s) { return s.local_search.neighbours; },
          [](tsp::SolverSettings& s, std::size_t n) { s.local_search.neighbours = n; })
      .def_property(
          "two_level_from",
          [](const tsp::SolverSettings& s) { return s.local_search.two_level_from; },
          [](tsp::SolverSettings& s, std::size_t n) { s.local_search.two_level_from = n; })
      .def_property(
          "ls_start",
          [](const tsp::SolverSettings& s) {
            return std::string(s.local_search.queue_changed_only ? "changed" : "all");
          },
          [](tsp::SolverSettings& s, const std::string& name) {
            if (name != "changed" && name != "all") unknown_name("ls_start", name, "changed, all");
            s.local_search.queue_changed_only = name == "changed";
          })
      .def_property(
          "backend",
          [](const tsp::SolverSettings& s) { return std::string(aco::to_string(s.backend)); },
          [](tsp::SolverSettings& s, const std::string& name) { s.backend = backend_from(name); });

  m.def("solve_settings", &solve, py::arg("instance"), py::arg("settings"),
        py::arg("problem_settings"), py::arg("termination"), py::arg("observer"),
        py::arg("colonies") = 1, py::arg("exchange_every") = 25, py::arg("topology") = "ring",
        "tsp::solve with explicit settings; antslam.tsp.solve takes keyword arguments");
}

}  // namespace antslam::python
