// antslam.clique: maximum (weighted) clique of a graph given by its edges, by the ants
// (clique/aco_search.hpp), by branch and bound (clique/exact.hpp) or greedily
// (clique/greedy.hpp): the searches that choose the loop closures of `antslam robust --method
// pcm-*`.

#include <pybind11/stl.h>

#include <string>
#include <utility>
#include <vector>

#include "antslam/aco/backend_factory.hpp"
#include "antslam/clique/aco_search.hpp"
#include "antslam/clique/exact.hpp"
#include "antslam/clique/greedy.hpp"
#include "arrays.hpp"
#include "bindings.hpp"
#include "interrupt.hpp"

namespace antslam::python {

namespace {

/// The graph on `vertices` vertices whose edges are the pairs (flat[2k], flat[2k + 1]).
clique::Graph graph_from(std::size_t vertices, const py::handle& flat_edges,
                         std::vector<double> weights) {
  const std::vector<std::uint32_t> flat = indices_from(flat_edges, "edges");
  if (flat.size() % 2 != 0) throw std::invalid_argument("edges: expected pairs of vertices");
  std::vector<clique::Edge> edges;
  edges.reserve(flat.size() / 2);
  for (std::size_t k = 0; k + 1 < flat.size(); k += 2) edges.emplace_back(flat[k], flat[k + 1]);
  return clique::Graph(vertices, edges, std::move(weights));
}

}  // namespace

void bind_clique(py::module_& m) {
  py::class_<clique::Graph>(m, "Graph",
                            "An undirected graph with vertex weights (clique/graph.hpp)")
      .def(py::init(&graph_from), py::arg("vertices"), py::arg("edges"),
           py::arg("weights") = std::vector<double>{})
      .def_property_readonly("size", &clique::Graph::size)
      .def("__len__", &clique::Graph::size)
      .def_property_readonly("unit_weights", &clique::Graph::unit_weights)
      .def("adjacent", &clique::Graph::adjacent, py::arg("i"), py::arg("j"))
      .def(
          "is_clique",
          [](const clique::Graph& g, const py::handle& vertices) {
            return clique::is_clique(g, indices_from(vertices, "vertices"));
          },
          py::arg("vertices"))
      .def(
          "weight_of",
          [](const clique::Graph& g, const py::handle& vertices) {
            return clique::weight_of(g, indices_from(vertices, "vertices"));
          },
          py::arg("vertices"));

  py::class_<clique::CliqueResult>(m, "Clique", "A clique found by one of the searches")
      .def_property_readonly("vertices",
                             [](const clique::CliqueResult& c) { return index_array(c.vertices); })
      .def_readonly("weight", &clique::CliqueResult::weight)
      .def_readonly("upper_bound", &clique::CliqueResult::upper_bound)
      .def_readonly("optimal", &clique::CliqueResult::optimal)
      .def_readonly("elapsed_s", &clique::CliqueResult::elapsed_s)
      .def("__repr__", [](const clique::CliqueResult& c) {
        return "<antslam.clique.Clique of " + std::to_string(c.vertices.size()) +
               " vertices: weight " + number_text(c.weight) + ", upper bound " +
               number_text(c.upper_bound) + (c.optimal ? ", proven maximum>" : ">");
      });

  py::class_<clique::AcoSearchSettings>(m, "AcoSettings", "clique/aco_search.hpp")
      .def(py::init<>())
      .def_readwrite("parameters", &clique::AcoSearchSettings::parameters)
      .def_readwrite("termination", &clique::AcoSearchSettings::termination)
      .def_readwrite("local_search", &clique::AcoSearchSettings::local_search)
      .def_readwrite("plateau_steps", &clique::AcoSearchSettings::plateau_steps)
      .def_readwrite("proof_nodes", &clique::AcoSearchSettings::proof_nodes)
      .def_readwrite("threads", &clique::AcoSearchSettings::threads)
      .def_property(
          "backend",
          [](const clique::AcoSearchSettings& s) { return std::string(aco::to_string(s.backend)); },
          [](clique::AcoSearchSettings& s, const std::string& name) {
            s.backend = backend_from(name);
          });

  m.def(
      "aco",
      [](const clique::Graph& g, const clique::AcoSearchSettings& settings) {
        aco::resolve(settings.backend, settings.threads);  // serial on several threads fails here
        const auto as_tuple = [](const clique::AcoSearchResult& r) {
          return py::object(
              py::make_tuple(r.clique, r.iterations, std::string(aco::to_string(r.reason))));
        };
        return as_tuple(run_interruptible(
            [&](PythonThread& python) {
              clique::AcoSearchSettings s = settings;
              s.termination.stop = python.stop_token();
              return clique::maximum_clique_aco(g, s);
            },
            as_tuple));
      },
      py::arg("graph"), py::arg("settings"), "(clique, iterations, stop reason)");
  m.def(
      "exact",
      [](const clique::Graph& g, double time_limit_s) {
        const clique::ExactResult r = [&] {
          const py::gil_scoped_release release;  // bounded by the time limit, not by Ctrl-C
          return clique::maximum_clique_exact(g, {.time_limit_s = time_limit_s});
        }();
        return py::make_tuple(r.clique, r.nodes);
      },
      py::arg("graph"), py::arg("time_limit_s"), "(clique, branch-and-bound nodes)");
  m.def(
      "greedy",
      [](const clique::Graph& g) {
        const py::gil_scoped_release release;
        return clique::greedy_clique(g);
      },
      py::arg("graph"));
}

}  // namespace antslam::python
