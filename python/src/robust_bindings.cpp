// antslam.slam, robust back ends: false loop closures added to a pose graph by the protocol of
// Suenderhauf & Protzel 2012 (slamgraph/outliers.hpp) and the back ends that decide which
// closures to trust (slamgraph/robust.hpp), as `antslam outliers` and `antslam robust` run them.

#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "antslam/clique/graph.hpp"
#include "antslam/slamgraph/consistency.hpp"
#include "antslam/slamgraph/outliers.hpp"
#include "antslam/slamgraph/robust.hpp"
#include "arrays.hpp"
#include "bindings.hpp"
#include "interrupt.hpp"
#include "slam_types.hpp"

namespace antslam::python {

namespace {

/// "a, b, c": the names of a table of {value, name, summary} (kRobustMethods, kOutlierKinds).
template <class Table>
std::string names_of(const Table& table) {
  std::string names;
  for (const auto& entry : table) names += (names.empty() ? "" : ", ") + std::string(entry.name);
  return names;
}

/// The vertex pairs of the graph's loop closures, in split.closures order.
std::vector<std::pair<std::size_t, std::size_t>> closure_pairs(const slam::PoseGraph& graph,
                                                               const slam::ChainSplit& split) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  pairs.reserve(split.closures.size());
  for (const std::size_t e : split.closures)
    pairs.emplace_back(graph.edges[e].from, graph.edges[e].to);
  return pairs;
}

py::array_t<bool> bool_array(const std::vector<bool>& values) {
  py::array_t<bool> out(static_cast<py::ssize_t>(values.size()));
  auto v = out.mutable_unchecked<1>();
  for (std::size_t k = 0; k < values.size(); ++k) v(static_cast<py::ssize_t>(k)) = values[k];
  return out;
}

/// A clique stage's clique, if it ran (None in Python).
std::optional<clique::CliqueResult> clique_of(const std::optional<slam::CliqueReport>& report) {
  if (!report) return std::nullopt;
  return report->clique;
}

/// The result with the graph's closures as vertex pairs, in split.closures order.
struct RobustRun {
  slam::RobustResult result;
  std::vector<std::pair<std::size_t, std::size_t>> closures;
};

}  // namespace

void bind_robust(py::module_& m) {
  py::class_<slam::OutlierSettings>(m, "OutlierSettings", "slamgraph/outliers.hpp")
      .def(py::init<>())
      .def_readwrite("count", &slam::OutlierSettings::count)
      .def_property(
          "kind",
          [](const slam::OutlierSettings& s) { return std::string(slam::to_string(s.kind)); },
          [](slam::OutlierSettings& s, const std::string& name) {
            const auto kind = slam::parse_outlier_kind(name);
            if (!kind) unknown_name("kind", name, names_of(slam::kOutlierKinds));
            s.kind = *kind;
          })
      .def_readwrite("group_size", &slam::OutlierSettings::group_size)
      .def_readwrite("local_window", &slam::OutlierSettings::local_window)
      .def_readwrite("seed", &slam::OutlierSettings::seed);
  m.def(
      "add_outliers",
      [](const NamedGraph& g, const slam::OutlierSettings& settings) {
        slam::SpoiledGraph spoiled = slam::add_outliers(g.graph, settings);
        return py::make_tuple(NamedGraph{std::move(spoiled.graph), g.name},
                              pairs_array(spoiled.outliers));
      },
      py::arg("graph"), py::arg("settings"), "(the spoiled graph, the false closures' pairs)");

  py::class_<slam::RobustSettings>(m, "RobustSettings", "slamgraph/robust.hpp")
      .def(py::init<>())
      .def_readwrite("inlier_confidence", &slam::RobustSettings::inlier_confidence)
      .def_readwrite("cauchy_scale", &slam::RobustSettings::cauchy_scale)
      .def_readwrite("dcs_phi", &slam::RobustSettings::dcs_phi)
      .def_readwrite("shown_noise", &slam::RobustSettings::shown_noise)
      .def_readwrite("check_clique", &slam::RobustSettings::check_clique)
      .def_readwrite("check_phi", &slam::RobustSettings::check_phi)
      .def_readwrite("recalibrate_below", &slam::RobustSettings::recalibrate_below)
      .def_readwrite("widen_noise", &slam::RobustSettings::widen_noise)
      .def_readwrite("prune_from", &slam::RobustSettings::prune_from)
      .def_property(
          "exact_time_limit_s", [](const slam::RobustSettings& s) { return s.exact.time_limit_s; },
          [](slam::RobustSettings& s, double seconds) { s.exact.time_limit_s = seconds; })
      .def_readwrite("aco", &slam::RobustSettings::aco)
      .def_readwrite("threads", &slam::RobustSettings::threads)
      .def_property(
          "backend",
          [](const slam::RobustSettings& s) { return std::string(aco::to_string(s.backend)); },
          [](slam::RobustSettings& s, const std::string& name) { s.backend = backend_from(name); });

  py::class_<RobustRun>(m, "RobustResult", "What a robust back end decided (slamgraph/robust.hpp)")
      .def_property_readonly(
          "method",
          [](const RobustRun& r) { return std::string(slam::to_string(r.result.method)); })
      .def_property_readonly("poses",
                             [](const RobustRun& r) { return poses_array(r.result.poses); })
      .def_property_readonly("closures", [](const RobustRun& r) { return pairs_array(r.closures); })
      .def_property_readonly("accepted",
                             [](const RobustRun& r) { return bool_array(r.result.accepted); })
      .def_property_readonly("clique",
                             [](const RobustRun& r) { return clique_of(r.result.clique); })
      .def_property_readonly("check_phi", [](const RobustRun& r) { return r.result.check_phi; })
      .def_property_readonly(
          "noise_scale",
          [](const RobustRun& r) -> std::optional<std::pair<double, double>> {
            if (!r.result.shown_noise) return std::nullopt;
            return std::pair{r.result.shown_noise->scale.xy, r.result.shown_noise->scale.theta};
          },
          "shown_noise: the (x-y, heading) scale of the stated deviations the graph shows")
      .def_property_readonly(
          "widened",
          [](const RobustRun& r) -> std::optional<std::pair<double, double>> {
            if (!r.result.widened) return std::nullopt;
            return std::pair{r.result.widened->xy, r.result.widened->theta};
          },
          "widen_noise: the (x-y, heading) scale decided at, None where no axis was widened")
      .def_property_readonly("variance_factor",
                             [](const RobustRun& r) { return r.result.variance_factor; })
      .def_property_readonly("core", [](const RobustRun& r) { return clique_of(r.result.core); })
      .def_property_readonly("consistent_pairs",
                             [](const RobustRun& r) -> std::optional<std::size_t> {
                               if (!r.result.clique) return std::nullopt;
                               return r.result.clique->consistent_pairs;
                             })
      .def_property_readonly("gnc_steps", [](const RobustRun& r) { return r.result.gnc_steps; })
      .def_property_readonly("consistency_s",
                             [](const RobustRun& r) { return r.result.consistency_s; })
      .def_property_readonly("clique_s", [](const RobustRun& r) { return r.result.clique_s; })
      .def_property_readonly("optimize_s", [](const RobustRun& r) { return r.result.optimize_s; })
      .def_property_readonly("total_s", [](const RobustRun& r) { return r.result.total_s; })
      .def("__repr__",
           [](const RobustRun& r) {
             const auto accepted =
                 std::count(r.result.accepted.begin(), r.result.accepted.end(), true);
             return "<antslam.slam.RobustResult " + std::string(slam::to_string(r.result.method)) +
                    ": " + std::to_string(accepted) + " of " +
                    std::to_string(r.result.accepted.size()) + " loop closures accepted, " +
                    number_text(r.result.total_s) + " s>";
           })
      .def(
          "kept_graph",
          [](const RobustRun& r, const NamedGraph& g) {
            return NamedGraph{slam::kept_graph(g.graph, r.result), g.name};
          },
          py::arg("graph"), "The optimised graph: the poses, the odometry and the kept closures");

  m.def("robust_method_names", [] { return names_of(slam::kRobustMethods); });
  m.def(
      "solve_robust",
      [](const NamedGraph& g, const std::string& method, const slam::RobustSettings& settings) {
        const auto kind = slam::parse_robust_method(method);
        if (!kind) unknown_name("method", method, names_of(slam::kRobustMethods));
        aco::resolve(settings.backend, settings.threads);  // serial on several threads fails here
        return run_interruptible([&](PythonThread& python) {
          slam::RobustSettings s = settings;
          s.aco.termination.stop = python.stop_token();
          RobustRun run{slam::solve_robust(g.graph, *kind, s, g.name), {}};
          run.closures = closure_pairs(g.graph, run.result.split);
          return run;
        });
      },
      py::arg("graph"), py::arg("method"), py::arg("settings"));
  m.def(
      "consistency",
      [](const NamedGraph& g, double confidence, std::size_t threads, const std::string& backend) {
        slam::ConsistencySettings settings;
        settings.confidence = confidence;
        settings.backend = backend_from(backend);
        settings.threads = threads;
        const slam::ChainSplit split = slam::split_chain(g.graph, g.name);
        const slam::ConsistencyGraph c = slam::pairwise_consistency(g.graph, split, settings);
        return py::make_tuple(clique::Graph(c.closures, c.pairs),
                              pairs_array(closure_pairs(g.graph, split)),
                              bool_array(c.odometry_consistent), c.threshold);
      },
      py::arg("graph"), py::arg("confidence"), py::arg("threads"), py::arg("backend"),
      "(consistency graph, closures' vertex pairs, odometry-consistent flags, threshold)");
}

}  // namespace antslam::python
