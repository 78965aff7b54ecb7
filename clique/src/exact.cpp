#include "antslam/clique/exact.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "antslam/clique/greedy.hpp"
#include "bits.hpp"
#include "colouring.hpp"

namespace antslam::clique {

namespace {

using Clock = std::chrono::steady_clock;

/// MCQ/BBMC on the renumbered graph. One Level of scratch per depth (reserved for the deepest
/// possible clique, so references to levels stay valid): a node allocates nothing once its depth
/// has been reached before.
class BranchAndBound {
 public:
  BranchAndBound(const detail::RenumberedGraph& graph, Clock::time_point deadline,
                 std::uint64_t max_nodes)
      : g_(graph), deadline_(deadline), max_nodes_(max_nodes) {
    levels_.reserve(graph.size() + 1);
  }

  /// Searches from the clique `start` (renumbered vertices); false if a budget stopped it.
  bool run(const std::vector<std::uint32_t>& start, double start_weight) {
    best_ = start;
    best_weight_ = start_weight;
    level(0).set = detail::all_bits(g_.size());
    expand(0, 0.0);
    return !stopped_;
  }

  const std::vector<std::uint32_t>& best() const { return best_; }
  std::uint64_t nodes() const { return nodes_; }

 private:
  struct Level {
    detail::Bits set;  // the candidates of the node at this depth
    detail::Bits remaining, open;
    std::vector<std::uint32_t> order;
    std::vector<double> bound;
  };

  Level& level(std::size_t depth) {
    if (levels_.size() <= depth) levels_.emplace_back();
    return levels_[depth];
  }

  void expand(std::size_t depth, double weight) {
    if (++nodes_ % 1024 == 0 && Clock::now() >= deadline_) stopped_ = true;
    if (max_nodes_ > 0 && nodes_ > max_nodes_) stopped_ = true;
    if (stopped_) return;
    Level& here = level(depth);
    detail::colour(g_, here.set, here.remaining, here.open, here.order, here.bound);
    for (std::size_t i = here.order.size(); i-- > 0;) {
      if (weight + here.bound[i] <= best_weight_) return;
      const std::uint32_t v = here.order[i];
      clique_.push_back(v);
      const double with_v = weight + g_.weight(v);
      const auto row = g_.row(v);
      Level& next = level(depth + 1);
      next.set.resize(here.set.size());
      for (std::size_t k = 0; k < here.set.size(); ++k) next.set[k] = here.set[k] & row[k];
      if (detail::any(next.set)) {
        expand(depth + 1, with_v);
      } else if (with_v > best_weight_) {
        best_ = clique_;
        best_weight_ = with_v;
      }
      clique_.pop_back();
      if (stopped_) return;
      detail::clear_bit(here.set, v);
    }
  }

  const detail::RenumberedGraph& g_;
  Clock::time_point deadline_;
  std::uint64_t max_nodes_;
  std::vector<Level> levels_;
  std::vector<std::uint32_t> clique_;
  std::vector<std::uint32_t> best_;
  double best_weight_ = 0.0;
  std::uint64_t nodes_ = 0;
  bool stopped_ = false;
};

}  // namespace

ExactResult maximum_clique_exact(const Graph& graph, const ExactSettings& settings,
                                 std::span<const std::uint32_t> start_from) {
  if (!std::isfinite(settings.time_limit_s) || settings.time_limit_s < 0.0)
    throw std::invalid_argument("exact clique search: time limit must be a finite number >= 0");
  if (!is_clique(graph, start_from))
    throw std::invalid_argument("exact clique search: the start is not a clique of the graph");
  const auto start = Clock::now();
  const Clock::time_point deadline =
      settings.time_limit_s > 0.0
          ? start + std::chrono::duration_cast<Clock::duration>(
                        std::chrono::duration<double>(settings.time_limit_s))
          : Clock::time_point::max();
  const detail::RenumberedGraph renumbered(graph);
  std::vector<std::uint32_t> renumbered_of(graph.size());
  for (std::uint32_t v = 0; v < graph.size(); ++v) renumbered_of[renumbered.original(v)] = v;

  // The first incumbent: the given clique unless the greedy one is heavier.
  const CliqueResult greedy = greedy_clique(graph);
  const double given_weight = weight_of(graph, start_from);
  const bool from_given = !start_from.empty() && given_weight >= greedy.weight;
  const std::span<const std::uint32_t> first =
      from_given ? start_from : std::span<const std::uint32_t>(greedy.vertices);
  std::vector<std::uint32_t> start_clique;
  for (const std::uint32_t v : first) start_clique.push_back(renumbered_of[v]);
  BranchAndBound search(renumbered, deadline, settings.max_nodes);
  const bool finished = search.run(start_clique, from_given ? given_weight : greedy.weight);

  ExactResult result;
  result.nodes = search.nodes();
  for (const std::uint32_t v : search.best())
    result.clique.vertices.push_back(renumbered.original(v));
  std::sort(result.clique.vertices.begin(), result.clique.vertices.end());
  result.clique.weight = weight_of(graph, result.clique.vertices);
  result.clique.optimal = finished;
  result.clique.upper_bound = finished ? result.clique.weight : greedy.upper_bound;
  result.clique.elapsed_s = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace antslam::clique
