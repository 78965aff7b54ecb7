#include "antslam/eval/report.hpp"

#include <cstdio>
#include <ostream>
#include <string>

#include "antslam/eval/relative_error.hpp"

namespace antslam::eval {

namespace {

template <typename... Args>
std::string format(const char* pattern, Args... args) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, args...);
  return buffer;
}

std::string statistics_row(const char* label, const ErrorStatistics& s) {
  return format("%-22s %10.4f %10.4f %10.4f %10.4f %10.4f %10.4f\n", label, s.rmse, s.mean,
                s.median, s.std, s.min, s.max);
}

std::string mean_std_row(const char* label, const MeanStd& s) {
  return format("  %-20s %10.4f +- %.4f\n", label, s.mean, s.std);
}

std::string rpe_step(const RpeSettings& settings) {
  if (settings.metres > 0.0) return format("%g m", settings.metres);
  return format("%zu frame%s", settings.frames, settings.frames == 1 ? "" : "s");
}

nlohmann::json to_json(const ErrorStatistics& s) {
  return {{"count", s.count}, {"rmse", s.rmse}, {"mean", s.mean}, {"median", s.median},
          {"std", s.std},     {"min", s.min},   {"max", s.max}};
}

nlohmann::json to_json(const MeanStd& s) {
  return {{"count", s.count}, {"mean", s.mean}, {"std", s.std}};
}

}  // namespace

void print_table(std::ostream& out, const Evaluation& e) {
  out << format("poses: estimate %zu, reference %zu, associated %zu (max dt %g s)\n",
                e.estimate_poses, e.reference_poses, e.associated, e.settings.max_dt);
  if (e.settings.align)
    out << format("alignment: x %.4f m, y %.4f m, theta %.4f deg\n", e.ate.alignment.x,
                  e.ate.alignment.y, degrees(e.ate.alignment.theta));
  else
    out << "alignment: none\n";
  out << format("%-22s %10s %10s %10s %10s %10s %10s\n", "", "rmse", "mean", "median", "std", "min",
                "max");
  out << statistics_row("ATE translation (m)", e.ate.translation_m);
  out << statistics_row("ATE rotation (deg)", e.ate.rotation_deg);
  out << statistics_row("RPE translation (m)", e.rpe.translation_m);
  out << statistics_row("RPE rotation (deg)", e.rpe.rotation_deg);
  out << format("RPE step: %s, %zu pose pairs\n", rpe_step(e.rpe.settings).c_str(),
                e.rpe.translation_m.count);
  if (!e.relations) return;
  const RelationsResult& r = *e.relations;
  out << format("relations (Kuemmerle et al. 2009): %zu scored, %zu skipped (max dt %g s)\n",
                r.used, r.skipped, e.settings.relations_max_dt);
  out << mean_std_row("translation (m)", r.translation_m);
  out << mean_std_row("translation^2 (m^2)", r.translation_squared_m2);
  out << mean_std_row("rotation (deg)", r.rotation_deg);
  out << mean_std_row("rotation^2 (deg^2)", r.rotation_squared_deg2);
}

nlohmann::json to_json(const Evaluation& e) {
  nlohmann::json json;
  json["max_dt_s"] = e.settings.max_dt;
  json["poses"] = {{"estimate", e.estimate_poses},
                   {"reference", e.reference_poses},
                   {"associated", e.associated}};
  json["alignment"] = e.settings.align
                          ? nlohmann::json{{"x_m", e.ate.alignment.x},
                                           {"y_m", e.ate.alignment.y},
                                           {"theta_deg", degrees(e.ate.alignment.theta)}}
                          : nlohmann::json(nullptr);
  json["ate"] = {{"translation_m", to_json(e.ate.translation_m)},
                 {"rotation_deg", to_json(e.ate.rotation_deg)}};
  const RpeSettings& step = e.rpe.settings;
  json["rpe"] = {{"step", step.metres > 0.0 ? nlohmann::json{{"metres", step.metres}}
                                            : nlohmann::json{{"frames", step.frames}}},
                 {"translation_m", to_json(e.rpe.translation_m)},
                 {"rotation_deg", to_json(e.rpe.rotation_deg)}};
  if (e.relations) {
    const RelationsResult& r = *e.relations;
    json["relations"] = {{"max_dt_s", e.settings.relations_max_dt},
                         {"used", r.used},
                         {"skipped", r.skipped},
                         {"translation_m", to_json(r.translation_m)},
                         {"translation_squared_m2", to_json(r.translation_squared_m2)},
                         {"rotation_deg", to_json(r.rotation_deg)},
                         {"rotation_squared_deg2", to_json(r.rotation_squared_deg2)}};
  }
  return json;
}

}  // namespace antslam::eval
