#include "antslam/slamgraph/optimize.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "antslam/slamgraph/search_baselines.hpp"
#include "antslam/slamgraph/slam_problem.hpp"
#include "optimize_detail.hpp"

namespace antslam::slam {

void validate(const OptimizeSettings& s) {
  const auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("optimize: ") + what);
  };
  require(s.iterations > 0 || s.time_limit_s > 0.0, "set iterations or a time limit");
  require(s.time_limit_s >= 0.0, "time limit must be >= 0");
  try {
    aco::validate(s.aco);  // the engine's parameters, checked where the engine defines them
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("optimize: ") + e.what());
  }
  require(s.aco.ants <= kMaxAnts, "ants must be <= 100000 (0: the variant's default)");
  require(s.ceres.max_iterations > 0, "ceres iterations must be positive");
  validate(s.refine);
  require(!s.islands || aco_variant(s.method).has_value(), "colonies need an ACO method");
  require(!s.islands || !s.refine_each_improvement,
          "refining every improvement needs one colony (the islands' paths travel rarely)");
}

namespace {

/// Every method: the ACO ones by their engine variant (named by the engine's table), the others
/// by name.
struct MethodInfo {
  Method method;
  std::optional<aco::Variant> variant;  ///< the engine variant it runs, if any
  std::string_view name;                ///< its name when it is not the variant's
};
constexpr std::array<MethodInfo, 12> kMethods{{
    {Method::ant_system, aco::Variant::ant_system, ""},
    {Method::elitist, aco::Variant::elitist, ""},
    {Method::rank_based, aco::Variant::rank_based, ""},
    {Method::acs, aco::Variant::acs, ""},
    {Method::mmas, aco::Variant::mmas, ""},
    {Method::hybrid, aco::Variant::hybrid, ""},
    {Method::hybrid_nlopt, aco::Variant::hybrid, "hybrid+nlopt"},
    {Method::nlopt, std::nullopt, "nlopt"},
    {Method::ceres, std::nullopt, "ceres"},
    {Method::ceres_robust, std::nullopt, "ceres-robust"},
    {Method::random, std::nullopt, "random"},
    {Method::exhaustive, std::nullopt, "exhaustive"},
}};
constexpr std::array<Method, kMethods.size()> kMethodList = [] {
  std::array<Method, kMethods.size()> list{};
  for (std::size_t i = 0; i < kMethods.size(); ++i) list[i] = kMethods[i].method;
  return list;
}();

const MethodInfo& info(Method m) {
  for (const MethodInfo& i : kMethods)
    if (i.method == m) return i;
  throw std::invalid_argument("unknown optimizer method");
}

void check_settings(const FragmentSet& set, const OptimizeSettings& s) {
  validate(s);
  if (!s.initial.empty() && s.initial.size() != set.layer_count())
    throw std::invalid_argument("optimize: initial has " + std::to_string(s.initial.size()) +
                                " alignments, expected " + std::to_string(set.layer_count()));
}

void run_random(const FragmentSet& set, const OptimizeSettings& s, detail::Recorder& recorder,
                OptimizeResult& result) {
  const SlamProblem problem(set);
  const std::size_t paths =
      s.aco.ants > 0 ? s.aco.ants : aco::default_ants(aco::Variant::hybrid, 0, false, false);
  const SearchResult r = random_search(
      problem, s.iterations, paths, s.seed, s.time_limit_s,
      [&](std::uint64_t round, std::uint64_t evaluations, double weight) {
        recorder.improve(round, evaluations, weight);
      },
      s.stop);
  result.choice = r.choice;
  result.evaluations = r.evaluations;
  result.iterations = r.evaluations / paths;
}

void run_exhaustive(const FragmentSet& set, const OptimizeSettings& s, detail::Recorder& recorder,
                    OptimizeResult& result) {
  const SearchResult r = exhaustive_search(set, s.max_exhaustive_paths);
  result.choice = r.choice;
  result.evaluations = r.evaluations;
  recorder.improve(0, r.evaluations, r.weight);
}

}  // namespace

std::string_view to_string(Method m) {
  const MethodInfo& i = info(m);
  return i.name.empty() ? aco::to_string(*i.variant) : i.name;
}

Method parse_method(std::string_view name) {
  std::string names;
  for (const Method m : kMethodList) {
    if (to_string(m) == name) return m;
    names += (names.empty() ? "" : ", ") + std::string(to_string(m));
  }
  throw std::invalid_argument("unknown method '" + std::string(name) + "' (expected one of " +
                              names + ")");
}

std::span<const Method> all_methods() { return kMethodList; }

bool is_discrete(Method m) {
  if (m == Method::hybrid_nlopt) return false;  // its choice is only the refinement's start
  return aco_variant(m).has_value() || m == Method::random || m == Method::exhaustive;
}

std::optional<aco::Variant> aco_variant(Method m) { return info(m).variant; }

RefineSettings refine_settings(const OptimizeSettings& settings) {
  RefineSettings refine = settings.refine;
  refine.stop = settings.stop;
  return refine;
}

OptimizeResult optimize(const FragmentSet& set, const OptimizeSettings& settings,
                        const OptimizeObserver& observer) {
  validate(set);
  check_settings(set, settings);
  OptimizeResult result;
  result.method = settings.method;
  detail::Recorder recorder(result, observer);
  const std::vector<Pose2> start =
      settings.initial.empty() ? mean_alignments(set) : settings.initial;
  switch (settings.method) {
    case Method::nlopt: {
      const RefineResult r =
          Refiner(set, refine_settings(settings))
              .refine(start, detail::stage_budget(settings.time_limit_s, recorder.elapsed(),
                                                  settings.refine.time_limit_s));
      result.alignments = r.alignments;
      result.evaluations = static_cast<std::uint64_t>(r.evaluations);
      break;
    }
    case Method::ceres:
    case Method::ceres_robust: {
      CeresSettings ceres = settings.ceres;
      ceres.time_limit_s =
          detail::stage_budget(settings.time_limit_s, recorder.elapsed(), ceres.time_limit_s);
      const CeresResult r =
          optimize_with_ceres(set, start, settings.method == Method::ceres_robust, ceres);
      result.alignments = relative_alignments(r.frames);
      result.iterations = static_cast<std::uint64_t>(r.iterations);
      break;
    }
    case Method::random:
      run_random(set, settings, recorder, result);
      break;
    case Method::exhaustive:
      run_exhaustive(set, settings, recorder, result);
      break;
    default:
      detail::run_aco(set, settings, recorder, result);
      break;
  }
  if (result.alignments.empty()) result.alignments = chosen_alignments(set, result.choice);
  result.frames = chain(result.alignments);
  result.scores = score(set, result.alignments);
  if (result.convergence.empty())
    recorder.improve(result.iterations, result.evaluations, result.scores.weight);
  result.elapsed_s = recorder.elapsed();
  return result;
}

}  // namespace antslam::slam
