#include "antslam/slamgraph/search_baselines.hpp"

#include <chrono>
#include <limits>
#include <stdexcept>
#include <string>

#include "antslam/aco/random.hpp"

namespace antslam::slam {

namespace {

/// Depth-first enumeration of the tree of samples (paper Fig. 3) with branch and bound.
class Enumerator {
 public:
  explicit Enumerator(const FragmentSet& set)
      : set_(set), frames_(set.fragments.size()), choice_(set.layer_count()) {
    closing_.resize(set.fragments.size());
    for (const LoopClosure& c : set.closures) closing_[c.to].push_back(&c);
  }

  SearchResult run() {
    descend(1, 0.0);
    return {best_choice_, best_, evaluations_};
  }

 private:
  void descend(std::size_t i, double partial) {
    if (i == set_.fragments.size()) {
      ++evaluations_;
      best_ = partial;  // descend() only gets here below the bound
      best_choice_ = choice_;
      return;
    }
    const Fragment& f = set_.fragments[i];
    for (std::size_t j = 0; j < f.samples.size(); ++j) {
      frames_[i] = frames_[i - 1] * f.samples[j];  // eq. (8)
      double w = partial + (1.0 - f.alignment->value(f.samples[j]));
      for (const LoopClosure* c : closing_[i])
        w += 1.0 - c->hypothesis.value(closure_pose(*c, frames_));
      if (w >= best_) continue;  // the remaining terms of eq. (10) are >= 0
      choice_[i - 1] = static_cast<std::uint32_t>(j);
      descend(i + 1, w);
    }
  }

  const FragmentSet& set_;
  std::vector<Pose2> frames_;
  std::vector<std::uint32_t> choice_;
  std::vector<std::vector<const LoopClosure*>> closing_;
  std::vector<std::uint32_t> best_choice_;
  double best_ = std::numeric_limits<double>::infinity();
  std::uint64_t evaluations_ = 0;
};

}  // namespace

std::uint64_t path_count(const FragmentSet& set) {
  std::uint64_t count = 1;
  for (std::size_t i = 1; i < set.fragments.size(); ++i) {
    const std::uint64_t m = set.fragments[i].samples.size();
    if (m != 0 && count > std::numeric_limits<std::uint64_t>::max() / m)
      return std::numeric_limits<std::uint64_t>::max();
    count *= m;
  }
  return count;
}

SearchResult exhaustive_search(const FragmentSet& set, std::uint64_t max_paths) {
  validate(set);
  const std::uint64_t paths = path_count(set);
  if (paths > max_paths)
    throw std::invalid_argument("exhaustive search over " + std::to_string(paths) +
                                " paths exceeds the limit of " + std::to_string(max_paths));
  return Enumerator(set).run();
}

SearchResult random_search(const SlamProblem& problem, std::uint64_t iterations, std::size_t paths,
                           std::uint64_t seed, double time_limit_s, const SearchObserver& observer,
                           std::stop_token stop) {
  if (paths == 0) throw std::invalid_argument("random search needs at least one path per round");
  if (iterations == 0 && !(time_limit_s > 0.0))
    throw std::invalid_argument("random search: set rounds or a time limit");
  const auto start = std::chrono::steady_clock::now();
  SearchResult result;
  result.weight = std::numeric_limits<double>::infinity();
  std::vector<std::uint32_t> choice(problem.layer_count());
  for (std::uint64_t t = 1; iterations == 0 || t <= iterations; ++t) {  // 0 rounds: no limit
    bool improved = false;
    for (std::size_t p = 0; p < paths; ++p) {
      aco::Rng rng = aco::ant_stream(seed, t, p);
      for (std::size_t l = 0; l < choice.size(); ++l)
        choice[l] = rng.below(static_cast<std::uint32_t>(problem.option_count(l)));
      const double w = problem.cost(choice);
      ++result.evaluations;
      if (w < result.weight) {
        result.weight = w;
        result.choice = choice;
        improved = true;
      }
    }
    if (improved && observer) observer(t, result.evaluations, result.weight);
    if (stop.stop_requested()) break;
    if (time_limit_s > 0.0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >=
            time_limit_s)
      break;
  }
  return result;
}

}  // namespace antslam::slam
