#include "antslam/slamgraph/result_io.hpp"

#include <charconv>
#include <fstream>
#include <iterator>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "antslam/aco/parameter_fields.hpp"
#include "antslam/version.hpp"
#include "json_reader.hpp"
#include "json_writer.hpp"

namespace antslam::slam {

namespace {

using detail::JsonField;
using json = nlohmann::ordered_json;

json statistics_json(const Statistics& s) {
  return {{"mean", s.mean}, {"std", s.std}, {"min", s.min}, {"max", s.max}};
}

Statistics read_statistics(const JsonField& f) {
  f.only({"mean", "std", "min", "max"});
  return {f.at("mean").number(), f.at("std").number(), f.at("min").number(), f.at("max").number()};
}

std::vector<Pose2> read_poses(const JsonField& f) {
  std::vector<Pose2> poses;
  const std::size_t n = f.array_size();
  for (std::size_t i = 0; i < n; ++i) poses.push_back(f.item(i).pose());
  return poses;
}

json best_json(const StudyResult& r) {
  const OptimizeResult& b = r.best;
  return {{"trial", r.best_trial},
          {"weight", b.scores.weight},
          {"chi2", b.scores.chi2},
          {"choice", b.choice},
          {"alignments", detail::poses_json(b.alignments)},
          {"frames", detail::poses_json(b.frames)},
          {"iterations", b.iterations},
          {"evaluations", b.evaluations}};
}

void read_best(const JsonField& f, StudyResult& r) {
  f.only({"trial", "weight", "chi2", "choice", "alignments", "frames", "iterations", "evaluations",
          "elapsed_s", "time_to_best_s"});
  OptimizeResult& b = r.best;
  b.method = r.method;
  r.best_trial = f.at("trial").integer();
  if (r.best_trial >= r.trials) f.at("trial").fail("is not below `trials`");
  b.scores = {f.at("weight").number(), f.at("chi2").number()};
  const JsonField choice = f.at("choice");
  for (std::size_t l = 0; l < choice.array_size(); ++l) {
    const std::uint64_t c = choice.item(l).integer();
    if (c > std::numeric_limits<std::uint32_t>::max())
      choice.item(l).fail("sample index too large");
    b.choice.push_back(static_cast<std::uint32_t>(c));
  }
  b.alignments = read_poses(f.at("alignments"));
  b.frames = read_poses(f.at("frames"));
  if (b.frames.size() != b.alignments.size() + 1)
    f.at("frames").fail("expected one pose more than `alignments`");
  if (!b.choice.empty() && b.choice.size() != b.alignments.size())
    choice.fail("expected as many entries as `alignments`");
  b.iterations = f.at("iterations").integer();
  b.evaluations = f.at("evaluations").integer();
  if (f.has("elapsed_s")) b.elapsed_s = f.at("elapsed_s").number();  // version 1 only
  if (f.has("time_to_best_s")) b.time_to_best_s = f.at("time_to_best_s").number();
}

json settings_json(const OptimizeSettings& s) {
  const aco::Parameters& p = s.aco;
  const RefineSettings& r = s.refine;
  json aco;
  aco::for_each_parameter(p, [&](const char* name, const auto& value) { aco[name] = value; });
  return {{"iterations", s.iterations},
          {"time_limit_s", s.time_limit_s},
          {"aco", aco},
          {"refine",
           {{"algorithm", std::string(to_string(r.algorithm))},
            {"bound_sigmas", r.bound_sigmas},
            {"max_evaluations", r.max_evaluations},
            {"relative_tolerance", r.relative_tolerance},
            {"time_limit_s", r.time_limit_s},
            {"lbfgs_memory", r.lbfgs_memory},
            {"graduated", r.graduated},
            {"graduation_factor", r.graduation_factor}}},
          {"refine_each_improvement", s.refine_each_improvement},
          {"ceres",
           {{"max_iterations", s.ceres.max_iterations},
            {"function_tolerance", s.ceres.function_tolerance},
            {"time_limit_s", s.ceres.time_limit_s}}},
          {"max_exhaustive_paths", s.max_exhaustive_paths},
          {"islands", s.islands ? json{{"colonies", s.islands->colonies},
                                       {"exchange_every", s.islands->exchange_every},
                                       {"topology", aco::to_string(s.islands->topology)}}
                                : json(nullptr)}};
}

/// An int field (counts stored as int by NLopt and Ceres).
int int_field(const JsonField& f) {
  const std::uint64_t v = f.integer();
  if (v > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) f.fail("too large");
  return static_cast<int>(v);
}

OptimizeSettings read_settings(const JsonField& f, const StudyResult& study) {
  f.only({"iterations", "time_limit_s", "aco", "refine", "refine_each_improvement", "ceres",
          "max_exhaustive_paths", "islands"});
  OptimizeSettings s;
  s.method = study.method;
  s.seed = study.seed;
  s.iterations = f.at("iterations").integer();
  s.time_limit_s = f.at("time_limit_s").number();
  const JsonField a = f.at("aco");
  std::vector<const char*> names;
  aco::for_each_parameter(s.aco, [&](const char* name, const auto&) { names.push_back(name); });
  a.only(names);
  aco::for_each_parameter(s.aco, [&](const char* name, auto& value) {
    using Field = std::remove_reference_t<decltype(value)>;
    const JsonField field = a.at(name);
    if constexpr (std::is_same_v<Field, bool>)
      value = field.boolean();
    else if constexpr (std::is_floating_point_v<Field>)
      value = field.number();
    else
      value = static_cast<Field>(field.integer());
  });
  const JsonField r = f.at("refine");
  r.only({"algorithm", "bound_sigmas", "max_evaluations", "relative_tolerance", "time_limit_s",
          "lbfgs_memory", "graduated", "graduation_factor"});
  try {
    s.refine.algorithm = parse_refine_algorithm(r.at("algorithm").string());
  } catch (const std::invalid_argument& e) {
    r.at("algorithm").fail(e.what());
  }
  s.refine.bound_sigmas = r.at("bound_sigmas").number();
  s.refine.max_evaluations = int_field(r.at("max_evaluations"));
  s.refine.relative_tolerance = r.at("relative_tolerance").number();
  s.refine.time_limit_s = r.at("time_limit_s").number();
  s.refine.lbfgs_memory = int_field(r.at("lbfgs_memory"));
  s.refine.graduated = r.at("graduated").boolean();
  s.refine.graduation_factor = r.at("graduation_factor").number();
  s.refine_each_improvement = f.at("refine_each_improvement").boolean();
  const JsonField c = f.at("ceres");
  c.only({"max_iterations", "function_tolerance", "time_limit_s"});
  s.ceres.max_iterations = int_field(c.at("max_iterations"));
  s.ceres.function_tolerance = c.at("function_tolerance").number();
  s.ceres.time_limit_s = c.at("time_limit_s").number();
  s.max_exhaustive_paths = f.at("max_exhaustive_paths").integer();
  if (!f.at("islands").json().is_null()) {
    const JsonField i = f.at("islands");
    i.only({"colonies", "exchange_every", "topology"});
    const std::optional<aco::Topology> topology = aco::parse_topology(i.at("topology").string());
    if (!topology) i.at("topology").fail("expected ring or full");
    s.islands = aco::IslandSettings{.colonies = i.at("colonies").integer(),
                                    .exchange_every = i.at("exchange_every").integer(),
                                    .topology = *topology};
  }
  try {
    validate(s);
  } catch (const std::invalid_argument& e) {
    f.fail(e.what());
  }
  return s;
}

/// The shortest text that reads back as the same double.
std::string shortest(double v) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, end);
}

}  // namespace

StudyResult summarize(const std::string& fragment_set, const OptimizeSettings& settings,
                      std::span<const OptimizeResult> trials) {
  if (trials.empty()) throw std::invalid_argument("summarize: no trials");
  StudyResult r;
  r.fragment_set = fragment_set;
  r.method = settings.method;
  r.seed = settings.seed;
  r.trials = trials.size();
  std::vector<double> weight, chi2, elapsed;
  for (const OptimizeResult& trial : trials) {
    weight.push_back(trial.scores.weight);
    chi2.push_back(trial.scores.chi2);
    elapsed.push_back(trial.elapsed_s);
  }
  r.best_trial = best_trial(trials);
  r.weight = statistics(weight);
  r.chi2 = statistics(chi2);
  r.elapsed_s = statistics(elapsed);
  r.best = trials[r.best_trial];
  r.best.convergence.clear();
  r.settings = settings;
  r.settings->threads = 1;  // neither decides a result: they are not part of it
  r.settings->backend = aco::BackendKind::automatic;
  r.settings->stop = {};
  r.settings->exchange = aco::in_process_exchange;
  if (r.settings->islands) {  // the whole archipelago, not this process's share of it
    r.settings->islands->first = 0;
    r.settings->islands->local = 0;
  }
  return r;
}

void write_result(std::ostream& out, const StudyResult& r) {
  json doc = {{"format", kResultFormat},
              {"version", kResultVersion},
              {"antslam_version", kVersion},
              {"fragment_set", r.fragment_set},
              {"method", std::string(to_string(r.method))},
              {"seed", r.seed},
              {"trials", r.trials},
              {"weight", statistics_json(r.weight)},
              {"chi2", statistics_json(r.chi2)},
              {"best", best_json(r)}};
  if (r.settings) doc["settings"] = settings_json(*r.settings);
  if (r.interrupted) {
    doc["interrupted"] = true;
    doc["interrupt_signal"] = r.interrupted->signal;
    doc["trials_requested"] = r.interrupted->trials_requested;
  }
  if (r.error)
    doc["trajectory_error"] = {{"rmse_m", r.error->rmse_m},
                               {"max_m", r.error->max_m},
                               {"rmse_deg", r.error->rmse_deg},
                               {"poses", r.error->poses}};
  detail::write_json(out, doc);
}

StudyResult read_result(std::istream& in, const std::string& source) {
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const nlohmann::json doc = detail::parse_json(text, source);
  const JsonField root(doc, source, "");
  detail::check_header(root, kResultFormat, kResultVersion);
  root.only({"format", "version", "antslam_version", "fragment_set", "method", "seed", "trials",
             "weight", "chi2", "elapsed_s", "best", "trajectory_error", "interrupted",
             "interrupt_signal", "trials_requested", "settings"});
  StudyResult r;
  r.fragment_set = root.at("fragment_set").string();
  try {
    r.method = parse_method(root.at("method").string());
  } catch (const std::invalid_argument& e) {
    root.at("method").fail(e.what());
  }
  r.seed = root.at("seed").integer();
  r.trials = root.at("trials").integer();
  if (r.trials == 0) root.at("trials").fail("must be >= 1");
  r.weight = read_statistics(root.at("weight"));
  r.chi2 = read_statistics(root.at("chi2"));
  if (root.has("elapsed_s")) r.elapsed_s = read_statistics(root.at("elapsed_s"));  // version 1
  read_best(root.at("best"), r);
  if (root.has("settings")) r.settings = read_settings(root.at("settings"), r);
  if (root.has("interrupted") && root.at("interrupted").boolean()) {
    r.interrupted = StudyInterruption{root.at("interrupt_signal").string(),
                                      root.at("trials_requested").integer()};
    if (r.interrupted->trials_requested < r.trials)
      root.at("trials_requested").fail("must be >= trials");
  }
  if (root.has("trajectory_error")) {
    const JsonField e = root.at("trajectory_error");
    e.only({"rmse_m", "max_m", "rmse_deg", "poses"});
    r.error = TrajectoryError{e.at("rmse_m").number(), e.at("max_m").number(),
                              e.at("rmse_deg").number(), e.at("poses").integer()};
  }
  return r;
}

StudyResult read_result_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  return read_result(in, path.string());
}

void write_trials_csv(std::ostream& out, std::span<const OptimizeResult> trials,
                      std::uint64_t study_seed) {
  out << "trial,seed,weight,chi2,iterations,evaluations\n";
  for (std::size_t t = 0; t < trials.size(); ++t) {
    const OptimizeResult& r = trials[t];
    out << t << ',' << trial_seed(study_seed, t) << ',' << shortest(r.scores.weight) << ','
        << shortest(r.scores.chi2) << ',' << r.iterations << ',' << r.evaluations << '\n';
  }
}

void write_convergence_csv(std::ostream& out, std::span<const OptimizeResult> trials) {
  out << "trial,iteration,evaluations,best_weight\n";
  for (std::size_t t = 0; t < trials.size(); ++t)
    for (const ConvergencePoint& p : trials[t].convergence)
      out << t << ',' << p.iteration << ',' << p.evaluations << ',' << shortest(p.best_weight)
          << '\n';
}

void write_times_json(std::ostream& out, std::span<const OptimizeResult> trials) {
  std::vector<double> elapsed;
  json per_trial = json::array();
  for (std::size_t t = 0; t < trials.size(); ++t) {
    const OptimizeResult& r = trials[t];
    elapsed.push_back(r.elapsed_s);
    json convergence = json::array();
    for (const ConvergencePoint& p : r.convergence)
      convergence.push_back(json::array({p.iteration, p.elapsed_s}));
    per_trial.push_back({{"trial", t},
                         {"elapsed_s", r.elapsed_s},
                         {"time_to_best_s", r.time_to_best_s},
                         {"convergence", convergence}});
  }
  detail::write_json(out, json{{"format", kTimesFormat},
                               {"version", 1},
                               {"elapsed_s", statistics_json(statistics(elapsed))},
                               {"trials", per_trial}});
}

}  // namespace antslam::slam
