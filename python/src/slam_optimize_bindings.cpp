// antslam.slam: every optimizer method on a fragment set or a pose graph, one trial or many
// (slamgraph/optimize.hpp, graph_optimize.hpp, trials.hpp), results with numpy poses.

#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "antslam/slamgraph/graph_optimize.hpp"
#include "antslam/slamgraph/result_io.hpp"
#include "arrays.hpp"
#include "bindings.hpp"
#include "engine.hpp"
#include "slam_types.hpp"

namespace antslam::python {

namespace {

std::string method_names() {
  std::string names;
  for (const slam::Method m : slam::all_methods())
    names += (names.empty() ? "" : ", ") + std::string(slam::to_string(m));
  return names;
}

/// The observers of a study, handed to the Python thread: every improvement of a single trial,
/// and the count of finished trials.
struct StudyObservers {
  slam::OptimizeObserver convergence;
  slam::TrialsObserver finished;
};

StudyObservers study_observers(const py::object& convergence, const py::object& finished,
                               PythonThread& python) {
  StudyObservers o;
  if (!convergence.is_none())
    o.convergence = [&convergence, &python](const slam::ConvergencePoint& p) {
      python.call([&] { convergence(p); });
    };
  if (!finished.is_none())
    o.finished = [&finished, &python](std::size_t done) { python.call([&] { finished(done); }); };
  return o;
}

slam::TrialSettings trial_settings(const slam::OptimizeSettings& s, std::size_t trials,
                                   std::size_t threads) {
  if (trials == 0) throw std::invalid_argument("trials must be >= 1");
  slam::validate(s);
  aco::resolve(s.backend, threads);
  return {trials, threads, s.backend};
}

std::vector<slam::OptimizeResult> optimize_set(const slam::FragmentSet& set,
                                               slam::OptimizeSettings settings, std::size_t trials,
                                               std::size_t threads, const py::object& convergence,
                                               const py::object& finished) {
  const slam::TrialSettings t = trial_settings(settings, trials, threads);
  return run_interruptible([&](PythonThread& python) {
    settings.stop = python.stop_token();
    const StudyObservers o = study_observers(convergence, finished, python);
    return slam::run_trials(set, settings, t, o.finished, o.convergence);
  });
}

std::vector<slam::OptimizeResult> optimize_graph(const NamedGraph& graph,
                                                 slam::OptimizeSettings settings,
                                                 std::size_t samples, std::size_t trials,
                                                 std::size_t threads, const py::object& convergence,
                                                 const py::object& finished) {
  const slam::TrialSettings t = trial_settings(settings, trials, threads);
  const slam::G2oImportSettings import{samples, settings.seed};  // as antslam optimize seeds them
  return run_interruptible([&](PythonThread& python) {
    settings.stop = python.stop_token();
    const StudyObservers o = study_observers(convergence, finished, python);
    return slam::run_trials(graph.graph, graph.name, settings, import, t, o.finished,
                            o.convergence);
  });
}

void bind_settings(py::module_& m) {
  py::class_<slam::RefineSettings>(m, "RefineSettings", "NLopt refinement (slamgraph/refine.hpp)")
      .def(py::init<>())
      .def_property(
          "algorithm",
          [](const slam::RefineSettings& s) { return std::string(slam::to_string(s.algorithm)); },
          [](slam::RefineSettings& s, const std::string& name) {
            s.algorithm = slam::parse_refine_algorithm(name);
          })
      .def_readwrite("bound_sigmas", &slam::RefineSettings::bound_sigmas)
      .def_readwrite("max_evaluations", &slam::RefineSettings::max_evaluations)
      .def_readwrite("relative_tolerance", &slam::RefineSettings::relative_tolerance)
      .def_readwrite("time_limit_s", &slam::RefineSettings::time_limit_s)
      .def_readwrite("lbfgs_memory", &slam::RefineSettings::lbfgs_memory)
      .def_readwrite("graduated", &slam::RefineSettings::graduated)
      .def_readwrite("graduation_factor", &slam::RefineSettings::graduation_factor);
  py::class_<slam::CeresSettings>(m, "CeresSettings", "slamgraph/ceres_baseline.hpp")
      .def(py::init<>())
      .def_readwrite("max_iterations", &slam::CeresSettings::max_iterations)
      .def_readwrite("function_tolerance", &slam::CeresSettings::function_tolerance)
      .def_readwrite("time_limit_s", &slam::CeresSettings::time_limit_s);
  py::class_<slam::OptimizeSettings>(m, "OptimizeSettings", "slamgraph/optimize.hpp")
      .def(py::init<>())
      .def_property(
          "method",
          [](const slam::OptimizeSettings& s) { return std::string(slam::to_string(s.method)); },
          [](slam::OptimizeSettings& s, const std::string& name) {
            s.method = slam::parse_method(name);
          })
      .def_readwrite("seed", &slam::OptimizeSettings::seed)
      .def_readwrite("iterations", &slam::OptimizeSettings::iterations)
      .def_readwrite("time_limit_s", &slam::OptimizeSettings::time_limit_s)
      .def_property(
          "backend",
          [](const slam::OptimizeSettings& s) { return std::string(aco::to_string(s.backend)); },
          [](slam::OptimizeSettings& s, const std::string& name) {
            s.backend = backend_from(name);
          })
      .def_readwrite("aco", &slam::OptimizeSettings::aco)
      .def_readwrite("refine", &slam::OptimizeSettings::refine)
      .def_readwrite("refine_each_improvement", &slam::OptimizeSettings::refine_each_improvement)
      .def_readwrite("ceres", &slam::OptimizeSettings::ceres)
      .def_readwrite("max_exhaustive_paths", &slam::OptimizeSettings::max_exhaustive_paths)
      .def_property(
          "initial", [](const slam::OptimizeSettings& s) { return poses_array(s.initial); },
          [](slam::OptimizeSettings& s, const DoubleArray& a) {
            s.initial = poses_from(a, "initial");
          },
          "Start of nlopt and ceres on a fragment set: N - 1 alignments; empty = the means");
  m.def("method_names", [] { return method_names(); });
}

void bind_results(py::module_& m) {
  py::class_<slam::ConvergencePoint>(m, "ConvergencePoint", "An improvement of the best weight")
      .def_readonly("iteration", &slam::ConvergencePoint::iteration)
      .def_readonly("evaluations", &slam::ConvergencePoint::evaluations)
      .def_readonly("elapsed_s", &slam::ConvergencePoint::elapsed_s)
      .def_readonly("best_weight", &slam::ConvergencePoint::best_weight)
      .def("__repr__", [](const slam::ConvergencePoint& p) {
        return "ConvergencePoint(iteration=" + std::to_string(p.iteration) +
               ", best_weight=" + std::to_string(p.best_weight) + ")";
      });
  py::class_<slam::OptimizeResult>(m, "Result", "One optimizer run (slamgraph/optimize.hpp)")
      .def_property_readonly(
          "method",
          [](const slam::OptimizeResult& r) { return std::string(slam::to_string(r.method)); })
      .def_property_readonly("weight",
                             [](const slam::OptimizeResult& r) { return r.scores.weight; })
      .def_property_readonly("chi2", [](const slam::OptimizeResult& r) { return r.scores.chi2; })
      .def_property_readonly("choice",
                             [](const slam::OptimizeResult& r) { return index_array(r.choice); })
      .def_property_readonly(
          "alignments", [](const slam::OptimizeResult& r) { return poses_array(r.alignments); })
      .def_property_readonly(
          "frames", [](const slam::OptimizeResult& r) { return poses_array(r.frames); },
          "World poses of the fragments (of the vertices of a pose graph)")
      .def_readonly("iterations", &slam::OptimizeResult::iterations)
      .def_readonly("evaluations", &slam::OptimizeResult::evaluations)
      .def_readonly("elapsed_s", &slam::OptimizeResult::elapsed_s)
      .def_readonly("time_to_best_s", &slam::OptimizeResult::time_to_best_s)
      .def_property_readonly(
          "convergence",
          [](const slam::OptimizeResult& r) {
            py::array_t<double> out(
                {static_cast<py::ssize_t>(r.convergence.size()), py::ssize_t{4}});
            auto v = out.mutable_unchecked<2>();
            for (std::size_t k = 0; k < r.convergence.size(); ++k) {
              const slam::ConvergencePoint& p = r.convergence[k];
              const auto i = static_cast<py::ssize_t>(k);
              v(i, 0) = static_cast<double>(p.iteration);
              v(i, 1) = static_cast<double>(p.evaluations);
              v(i, 2) = p.elapsed_s;
              v(i, 3) = p.best_weight;
            }
            return out;
          },
          "Every improvement: (iteration, evaluations, elapsed_s, best_weight) rows")
      .def("__repr__", [](const slam::OptimizeResult& r) {
        return "<antslam.slam.Result " + std::string(slam::to_string(r.method)) + ": weight " +
               std::to_string(r.scores.weight) + ", chi2 " + std::to_string(r.scores.chi2) + ">";
      });
  py::class_<slam::Statistics>(m, "Statistics", "mean, sample standard deviation, min, max")
      .def_readonly("mean", &slam::Statistics::mean)
      .def_readonly("std", &slam::Statistics::std)
      .def_readonly("min", &slam::Statistics::min)
      .def_readonly("max", &slam::Statistics::max)
      .def("__repr__", [](const slam::Statistics& s) {
        return "Statistics(mean=" + std::to_string(s.mean) + ", std=" + std::to_string(s.std) +
               ", min=" + std::to_string(s.min) + ", max=" + std::to_string(s.max) + ")";
      });
  py::class_<slam::StudyResult>(m, "Summary", "Statistics of a study's trials (result_io.hpp)")
      .def_readonly("weight", &slam::StudyResult::weight)
      .def_readonly("chi2", &slam::StudyResult::chi2)
      .def_readonly("elapsed_s", &slam::StudyResult::elapsed_s)
      .def_readonly("best_trial", &slam::StudyResult::best_trial)
      .def_readonly("trials", &slam::StudyResult::trials)
      .def("__repr__", [](const slam::StudyResult& r) {
        return "<antslam.slam.Summary of " + std::to_string(r.trials) + " trials: weight " +
               number_text(r.weight.mean) + " +- " + number_text(r.weight.std) + " (best " +
               number_text(r.weight.min) + ", trial " + std::to_string(r.best_trial) + ")>";
      });
  m.def(
      "summarize",
      [](const std::string& name, const slam::OptimizeSettings& settings,
         const std::vector<slam::OptimizeResult>& trials) {
        return slam::summarize(name, settings, trials);
      },
      py::arg("name"), py::arg("settings"), py::arg("trials"));
  m.def("trial_seed", &slam::trial_seed, py::arg("seed"), py::arg("trial"),
        "The seed of trial t of a study seeded with `seed`");
}

}  // namespace

void bind_slam_optimize(py::module_& m) {
  bind_settings(m);
  bind_results(m);
  m.def("optimize_set", &optimize_set, py::arg("set"), py::arg("settings"), py::arg("trials"),
        py::arg("threads"), py::arg("convergence"), py::arg("finished"));
  m.def("optimize_graph", &optimize_graph, py::arg("graph"), py::arg("settings"),
        py::arg("samples"), py::arg("trials"), py::arg("threads"), py::arg("convergence"),
        py::arg("finished"));
}

}  // namespace antslam::python
