// antslam.mapping: the whole pipeline on a CARMEN log in one call (mapping/pipeline.hpp).

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <string>

#include "antslam/frontend/report.hpp"
#include "antslam/mapping/pipeline.hpp"
#include "antslam/mapping/report.hpp"
#include "arrays.hpp"
#include "bindings.hpp"
#include "interrupt.hpp"

namespace antslam::python {

namespace {

py::array_t<std::uint8_t> image_array(const frontend::Image& image) {
  py::array_t<std::uint8_t> out({static_cast<py::ssize_t>(image.height()),
                                 static_cast<py::ssize_t>(image.width()), py::ssize_t{3}});
  auto v = out.mutable_unchecked<3>();
  for (std::size_t y = 0; y < image.height(); ++y)
    for (std::size_t x = 0; x < image.width(); ++x) {
      const frontend::Rgb& c = image.at(x, y);
      const auto row = static_cast<py::ssize_t>(y), column = static_cast<py::ssize_t>(x);
      v(row, column, 0) = c.r;
      v(row, column, 1) = c.g;
      v(row, column, 2) = c.b;
    }
  return out;
}

py::list closures_list(const mapping::MappingResult& r) {
  py::list out;
  for (std::size_t c = 0; c < r.after.size(); ++c) {
    py::dict d;
    d["from"] = r.after[c].from;
    d["to"] = r.after[c].to;
    d["before_sigmas"] = r.before[c].mahalanobis;
    d["after_sigmas"] = r.after[c].mahalanobis;
    out.append(d);
  }
  return out;
}

/// The run and the settings it ran with (for its report).
struct PipelineRun {
  mapping::PipelineResult result;
  mapping::PipelineSettings settings;
  std::string log;
};

PipelineRun run_pipeline(const std::filesystem::path& log, mapping::PipelineSettings settings,
                         const std::optional<std::filesystem::path>& reference,
                         const py::object& observer) {
  mapping::validate(settings);
  return run_interruptible([&](PythonThread& python) {
    settings.mapping.optimize.stop = python.stop_token();
    mapping::StageObserver stage;
    if (!observer.is_none())
      stage = [&](std::string_view name, bool final) {
        python.call([&] { observer(std::string(name), final); });
      };
    mapping::PipelineResult r =
        mapping::run_pipeline(log, settings, reference.value_or(std::filesystem::path{}), stage);
    return PipelineRun{std::move(r), settings, log.string()};
  });
}

void bind_settings(py::module_& m) {
  py::class_<frontend::SensorOverrides>(m, "SensorOverrides",
                                        "Laser geometry that wins over the log's (radians, metres)")
      .def(py::init<>())
      .def_readwrite("field_of_view", &frontend::SensorOverrides::field_of_view)
      .def_readwrite("first_angle", &frontend::SensorOverrides::first_angle)
      .def_readwrite("max_range", &frontend::SensorOverrides::max_range)
      .def_readwrite("laser_offset", &frontend::SensorOverrides::laser_offset);
  using Fs = frontend::FrontendSettings;
  py::class_<Fs>(m, "FrontendSettings", "Scan matcher, fragments, loop closures")
      .def(py::init<>())
      .def_property(
          "fragment_length", [](const Fs& s) { return s.fragmentation.length; },
          [](Fs& s, double v) { s.fragmentation.length = v; })
      .def_property(
          "samples", [](const Fs& s) { return s.fragmentation.samples; },
          [](Fs& s, std::size_t v) { s.fragmentation.samples = v; })
      .def_property(
          "seed", [](const Fs& s) { return s.fragmentation.seed; },
          [](Fs& s, std::uint64_t v) { s.fragmentation.seed = v; })
      .def_property(
          "alignment",
          [](const Fs& s) { return std::string(frontend::to_string(s.fragmentation.covariance)); },
          [](Fs& s, const std::string& name) {
            s.fragmentation.covariance = frontend::parse_alignment_covariance(name);
          })
      .def_property(
          "covariance_scale", [](const Fs& s) { return s.fragmentation.covariance_scale; },
          [](Fs& s, double v) { s.fragmentation.covariance_scale = v; })
      .def_property(
          "temperature", [](const Fs& s) { return s.matcher.temperature; },
          [](Fs& s, double v) { s.matcher.temperature = v; })
      .def_property(
          "closures", [](const Fs& s) { return s.closure.enabled; },
          [](Fs& s, bool v) { s.closure.enabled = v; })
      .def_property(
          "closure_min_score", [](const Fs& s) { return s.closure.min_score; },
          [](Fs& s, double v) { s.closure.min_score = v; })
      .def_property(
          "closure_max_second", [](const Fs& s) { return s.closure.max_second_ratio; },
          [](Fs& s, double v) { s.closure.max_second_ratio = v; })
      .def_property(
          "closure_temperature", [](const Fs& s) { return s.closure.temperature; },
          [](Fs& s, double v) { s.closure.temperature = v; });
  py::class_<mapping::MappingSettings>(m, "MappingSettings", "Optimizer, trials, threads")
      .def(py::init<>())
      .def_readwrite("optimize", &mapping::MappingSettings::optimize)
      .def_readwrite("trials", &mapping::MappingSettings::trials)
      .def_readwrite("threads", &mapping::MappingSettings::threads)
      .def_property(
          "backend",
          [](const mapping::MappingSettings& s) { return std::string(aco::to_string(s.backend)); },
          [](mapping::MappingSettings& s, const std::string& name) {
            s.backend = backend_from(name);
          });
  py::class_<mapping::PipelineSettings>(m, "PipelineSettings", "mapping/pipeline.hpp")
      .def(py::init<>())
      .def_readwrite("sensor", &mapping::PipelineSettings::sensor)
      .def_readwrite("frontend", &mapping::PipelineSettings::frontend)
      .def_readwrite("mapping", &mapping::PipelineSettings::mapping)
      .def_property(
          "resolution", [](const mapping::PipelineSettings& s) { return s.map.resolution; },
          [](mapping::PipelineSettings& s, double v) { s.map.resolution = v; })
      .def_readwrite("draw_maps", &mapping::PipelineSettings::draw_maps);
}

void bind_result(py::module_& m) {
  py::class_<PipelineRun>(m, "PipelineResult", "mapping::PipelineResult")
      .def_property_readonly("fragment_set",
                             [](const PipelineRun& p) { return p.result.frontend.fragment_set; })
      .def_property_readonly("scans",
                             [](const PipelineRun& p) { return p.result.log.scans.size(); })
      .def_property_readonly(
          "trajectory",
          [](const PipelineRun& p) { return trajectory_array(p.result.mapping.corrected); },
          "Every scan's corrected pose, (n, 4) of (t, x, y, theta)")
      .def_property_readonly(
          "scan_matcher_trajectory",
          [](const PipelineRun& p) { return trajectory_array(p.result.frontend.trajectory); })
      .def_property_readonly("trials", [](const PipelineRun& p) { return p.result.mapping.trials; })
      .def_property_readonly("best_trial",
                             [](const PipelineRun& p) { return p.result.mapping.best; })
      .def_property_readonly("scan_matcher_scores",
                             [](const PipelineRun& p) {
                               return py::make_tuple(p.result.mapping.scan_matcher.weight,
                                                     p.result.mapping.scan_matcher.chi2);
                             })
      .def_property_readonly(
          "closures", [](const PipelineRun& p) { return closures_list(p.result.mapping); },
          "Per closure: fragments and Mahalanobis distance before and after")
      .def_property_readonly("evaluation",
                             [](const PipelineRun& p) -> py::object {
                               if (!p.result.evaluation) return py::none();
                               py::dict d;
                               d["scan_matcher"] = p.result.evaluation->scan_matcher;
                               d["optimized"] = p.result.evaluation->optimized;
                               return d;
                             })
      .def_property_readonly("times",
                             [](const PipelineRun& p) {
                               const mapping::PipelineTimes& t = p.result.times;
                               py::dict d;
                               d["read_s"] = t.read_s;
                               d["frontend_s"] = t.frontend_s;
                               d["optimization_s"] = t.optimization_s;
                               d["maps_s"] = t.maps_s;
                               d["total_s"] = t.total_s;
                               return d;
                             })
      .def_property_readonly(
          "maps",
          [](const PipelineRun& p) -> py::object {
            if (!p.result.maps) return py::none();
            py::dict d;
            d["scan_matcher"] = image_array(p.result.maps->scan_matcher);
            d["optimized"] = image_array(p.result.maps->optimized);
            d["average"] = image_array(p.result.maps->average);
            return d;
          },
          "The three maps as (height, width, 3) uint8 images, if drawn")
      .def(
          "report",
          [](const PipelineRun& p) {
            return mapping::report_json(p.log, p.settings, p.result).dump(2);
          },
          "The JSON report antslam map writes")
      .def("__repr__", [](const PipelineRun& p) {
        const slam::FragmentSet& set = p.result.frontend.fragment_set;
        return "<antslam.mapping.PipelineResult of " + p.log + ": " +
               std::to_string(p.result.log.scans.size()) + " scans, " +
               std::to_string(set.fragments.size()) + " fragments, " +
               std::to_string(set.closures.size()) + " loop closures, " +
               std::to_string(p.result.mapping.trials.size()) + " trials, weight " +
               number_text(p.result.mapping.scores.weight) + ">";
      });
}

}  // namespace

void bind_mapping(py::module_& m) {
  bind_settings(m);
  bind_result(m);
  m.def("run_pipeline_settings", &run_pipeline, py::arg("log"), py::arg("settings"),
        py::arg("reference"), py::arg("observer"));
}

}  // namespace antslam::python
