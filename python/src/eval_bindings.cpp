// antslam.eval: trajectory evaluation (ATE, RPE, the relations metric) of numpy trajectories or
// TUM files (eval/evaluation.hpp), and TUM files themselves.

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <string>
#include <vector>

#include "antslam/eval/evaluation.hpp"
#include "antslam/eval/relations.hpp"
#include "antslam/eval/report.hpp"
#include "antslam/io/atomic_file.hpp"
#include "arrays.hpp"
#include "bindings.hpp"

namespace antslam::python {

namespace {

eval::Evaluation evaluate(const DoubleArray& estimate, const DoubleArray& reference,
                          const eval::EvaluationSettings& settings,
                          const std::optional<std::filesystem::path>& relations) {
  const slam::Trajectory e = trajectory_from(estimate, "estimate");
  const slam::Trajectory r = trajectory_from(reference, "reference");
  if (e.empty()) throw std::invalid_argument("estimate: no poses");
  if (r.empty()) throw std::invalid_argument("reference: no poses");
  std::vector<eval::Relation> pairs;
  if (relations) pairs = eval::read_relations_file(*relations);
  const py::gil_scoped_release release;
  return eval::evaluate(e, r, settings, pairs);
}

}  // namespace

void bind_eval(py::module_& m) {
  py::class_<eval::RpeSettings>(m, "RpeSettings")
      .def(py::init<>())
      .def_readwrite("frames", &eval::RpeSettings::frames)
      .def_readwrite("metres", &eval::RpeSettings::metres);
  py::class_<eval::EvaluationSettings>(m, "EvaluationSettings", "eval/evaluation.hpp")
      .def(py::init<>())
      .def_readwrite("max_dt", &eval::EvaluationSettings::max_dt)
      .def_readwrite("align", &eval::EvaluationSettings::align)
      .def_readwrite("rpe", &eval::EvaluationSettings::rpe)
      .def_readwrite("relations_max_dt", &eval::EvaluationSettings::relations_max_dt);
  py::class_<eval::ErrorStatistics>(m, "ErrorStatistics")
      .def_readonly("count", &eval::ErrorStatistics::count)
      .def_readonly("rmse", &eval::ErrorStatistics::rmse)
      .def_readonly("mean", &eval::ErrorStatistics::mean)
      .def_readonly("median", &eval::ErrorStatistics::median)
      .def_readonly("std", &eval::ErrorStatistics::std)
      .def_readonly("min", &eval::ErrorStatistics::min)
      .def_readonly("max", &eval::ErrorStatistics::max);
  py::class_<eval::MeanStd>(m, "MeanStd")
      .def_readonly("count", &eval::MeanStd::count)
      .def_readonly("mean", &eval::MeanStd::mean)
      .def_readonly("std", &eval::MeanStd::std);
  py::class_<eval::AteResult>(m, "Ate")
      .def_property_readonly("alignment",
                             [](const eval::AteResult& a) {
                               return py::make_tuple(a.alignment.x, a.alignment.y,
                                                     a.alignment.theta);
                             })
      .def_readonly("translation_m", &eval::AteResult::translation_m)
      .def_readonly("rotation_deg", &eval::AteResult::rotation_deg);
  py::class_<eval::RpeResult>(m, "Rpe")
      .def_readonly("translation_m", &eval::RpeResult::translation_m)
      .def_readonly("rotation_deg", &eval::RpeResult::rotation_deg);
  py::class_<eval::RelationsResult>(m, "Relations")
      .def_readonly("used", &eval::RelationsResult::used)
      .def_readonly("skipped", &eval::RelationsResult::skipped)
      .def_readonly("translation_m", &eval::RelationsResult::translation_m)
      .def_readonly("translation_squared_m2", &eval::RelationsResult::translation_squared_m2)
      .def_readonly("rotation_deg", &eval::RelationsResult::rotation_deg)
      .def_readonly("rotation_squared_deg2", &eval::RelationsResult::rotation_squared_deg2);
  py::class_<eval::Evaluation>(m, "Evaluation", "What antslam eval reports")
      .def_readonly("estimate_poses", &eval::Evaluation::estimate_poses)
      .def_readonly("reference_poses", &eval::Evaluation::reference_poses)
      .def_readonly("associated", &eval::Evaluation::associated)
      .def_readonly("ate", &eval::Evaluation::ate)
      .def_readonly("rpe", &eval::Evaluation::rpe)
      .def_readonly("relations", &eval::Evaluation::relations)
      .def(
          "to_json", [](const eval::Evaluation& e) { return eval::to_json(e).dump(2); },
          "The JSON antslam eval --json writes (without the file names)")
      .def("__repr__", [](const eval::Evaluation& e) {
        return "<antslam.eval.Evaluation of " + std::to_string(e.associated) +
               " associated poses: ATE " + number_text(e.ate.translation_m.rmse) + " m rmse, " +
               number_text(e.ate.translation_m.max) + " m max>";
      });
  py::class_<slam::TrajectoryError>(m, "FramesError", "ATE of index-matched poses")
      .def_readonly("rmse_m", &slam::TrajectoryError::rmse_m)
      .def_readonly("max_m", &slam::TrajectoryError::max_m)
      .def_readonly("rmse_deg", &slam::TrajectoryError::rmse_deg)
      .def_readonly("poses", &slam::TrajectoryError::poses);

  m.def("evaluate_arrays", &evaluate, py::arg("estimate"), py::arg("reference"),
        py::arg("settings"), py::arg("relations"));
  m.def(
      "frames_error",
      [](const DoubleArray& frames, const DoubleArray& reference) {
        return eval::frames_error(poses_from(frames, "frames"), poses_from(reference, "reference"));
      },
      py::arg("frames"), py::arg("reference"),
      "Poses without timestamps against reference poses of the same index, rigidly aligned");
  m.def(
      "read_tum",
      [](const std::filesystem::path& path) { return trajectory_array(slam::read_tum_file(path)); },
      py::arg("path"), "A TUM trajectory as an (n, 4) array of (t, x, y, theta)");
  m.def(
      "write_tum",
      [](const std::filesystem::path& path, const DoubleArray& trajectory) {
        const slam::Trajectory t = trajectory_from(trajectory, "trajectory");
        io::write_atomically(path, [&](std::ostream& out) { slam::write_tum(out, t); });
      },
      py::arg("path"), py::arg("trajectory"), "Writes an (n, 4) trajectory as TUM (atomically)");
}

}  // namespace antslam::python
