#include "engine.hpp"

#include <pybind11/stl.h>

#include <string>

#include "arrays.hpp"

namespace antslam::python {

aco::Observer colony_observer(const py::object& observer, PythonThread& python) {
  if (observer.is_none()) return {};
  return [&observer, &python](const aco::IterationReport& r) {
    IterationInfo info{r.iteration,      r.elapsed_s,
                       r.iteration_best, r.global_best,
                       r.improved,       {r.global_best_path.begin(), r.global_best_path.end()}};
    python.call([&] { observer(std::move(info)); });
  };
}

void bind_engine(py::module_& m) {
  py::class_<aco::Parameters>(m, "Parameters", "Every knob of every ACO variant (aco/variants.hpp)")
      .def(py::init<>())
      .def_property(
          "variant",
          [](const aco::Parameters& p) { return std::string(aco::to_string(p.variant)); },
          [](aco::Parameters& p, const std::string& name) {
            const auto v = aco::parse_variant(name);
            if (!v) {
              std::string names;
              for (const std::string& n : aco::variant_names())
                names += (names.empty() ? "" : ", ") + n;
              unknown_name("variant", name, names);
            }
            p.variant = *v;
          })
      .def_readwrite("ants", &aco::Parameters::ants)
      .def_readwrite("alpha", &aco::Parameters::alpha)
      .def_readwrite("beta", &aco::Parameters::beta)
      .def_readwrite("rho", &aco::Parameters::rho)
      .def_readwrite("seed", &aco::Parameters::seed)
      .def_readwrite("local_search_ants", &aco::Parameters::local_search_ants)
      .def_readwrite("q0", &aco::Parameters::q0)
      .def_readwrite("xi", &aco::Parameters::xi)
      .def_readwrite("elite_weight", &aco::Parameters::elite_weight)
      .def_readwrite("rank_width", &aco::Parameters::rank_width)
      .def_readwrite("p_best", &aco::Parameters::p_best)
      .def_readwrite("restarts", &aco::Parameters::restarts)
      .def_readwrite("restart_stagnant", &aco::Parameters::restart_stagnant)
      .def_readwrite("p0", &aco::Parameters::p0)
      .def_readwrite("glob_best_freq", &aco::Parameters::glob_best_freq)
      .def_readwrite("tau_max", &aco::Parameters::tau_max)
      .def_readwrite("tau_init", &aco::Parameters::tau_init)
      .def_readwrite("hybrid_deposit", &aco::Parameters::hybrid_deposit);

  py::class_<aco::Termination>(m, "Termination", "When a run stops (aco/termination.hpp)")
      .def(py::init<>())
      .def_readwrite("max_iterations", &aco::Termination::max_iterations)
      .def_readwrite("time_limit_s", &aco::Termination::time_limit_s)
      .def_readwrite("cpu_time_limit_s", &aco::Termination::cpu_time_limit_s)
      .def_readwrite("target_cost", &aco::Termination::target_cost)
      .def_readwrite("stagnation_iterations", &aco::Termination::stagnation_iterations);

  py::class_<IterationInfo>(m, "IterationInfo", "What an observer hears after every iteration")
      .def_readonly("iteration", &IterationInfo::iteration)
      .def_readonly("elapsed_s", &IterationInfo::elapsed_s)
      .def_readonly("iteration_best", &IterationInfo::iteration_best)
      .def_readonly("global_best", &IterationInfo::global_best)
      .def_readonly("improved", &IterationInfo::improved)
      .def_property_readonly("best", [](const IterationInfo& i) { return index_array(i.best); })
      .def("__repr__", [](const IterationInfo& i) {
        return "IterationInfo(iteration=" + std::to_string(i.iteration) +
               ", global_best=" + std::to_string(i.global_best) + ")";
      });

  py::class_<aco::RunResult>(m, "Run", "A colony run: the best solution and what ran")
      .def_property_readonly("cost", [](const aco::RunResult& r) { return r.best.cost; })
      .def_property_readonly("path",
                             [](const aco::RunResult& r) { return index_array(r.best.path); })
      .def_readonly("iterations", &aco::RunResult::iterations)
      .def_readonly("best_iteration", &aco::RunResult::best_iteration)
      .def_readonly("elapsed_s", &aco::RunResult::elapsed_s)
      .def_readonly("time_to_best_s", &aco::RunResult::time_to_best_s)
      .def_property_readonly(
          "stop_reason",
          [](const aco::RunResult& r) { return std::string(aco::to_string(r.reason)); })
      .def_property_readonly("variant",
                             [](const aco::RunResult& r) {
                               return r.settings.variant
                                          ? std::string(aco::to_string(*r.settings.variant))
                                          : std::string();
                             })
      .def_property_readonly("ants", [](const aco::RunResult& r) { return r.settings.colony.ants; })
      .def_property_readonly("rho", [](const aco::RunResult& r) { return r.settings.rho; })
      .def_property_readonly(
          "backend",
          [](const aco::RunResult& r) { return std::string(aco::to_string(r.settings.backend)); })
      .def_property_readonly("threads", [](const aco::RunResult& r) { return r.settings.threads; })
      .def("__repr__", [](const aco::RunResult& r) {
        const std::string variant =
            r.settings.variant ? std::string(aco::to_string(*r.settings.variant)) + ": " : "";
        return "<antslam.aco.Run " + variant + "cost " + number_text(r.best.cost) + " after " +
               std::to_string(r.iterations) + " iterations (" +
               std::string(aco::to_string(r.reason)) + "), best at iteration " +
               std::to_string(r.best_iteration) + ", " + number_text(r.elapsed_s) + " s>";
      });
}

}  // namespace antslam::python
