#pragma once
// The two problem families the engine solves. A problem plugs in by satisfying one concept;
// the engine never sees anything else of it.

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>

namespace antslam::aco {

/// Layered-choice problem: the ant picks one option in each layer, in order; the cost is a
/// function of the whole choice. This is the shape of AntSLAM (paper Sec. III-B: one sample per
/// fragment, weight of eq. 10).
template <class P>
concept LayeredProblem = requires(const P& p, std::size_t layer,
                                  std::span<const std::uint32_t> choice) {
  { p.layer_count() } -> std::convertible_to<std::size_t>;
  { p.option_count(layer) } -> std::convertible_to<std::size_t>;
  { p.cost(choice) } -> std::convertible_to<double>;
};

/// Optional heuristic desirability eta >= 0 of an option (1 when the problem gives none, as in
/// AntSLAM's eq. 11).
template <class P>
concept LayeredProblemWithHeuristic = LayeredProblem<P> &&
    requires(const P& p, std::size_t layer, std::size_t option) {
  { p.heuristic(layer, option) } -> std::convertible_to<double>;
};

/// Symmetric permutation problem (TSP): the ant builds a closed tour over size() nodes.
/// candidates(i) lists i's nearest neighbours, nearest first, all lists of equal length.
template <class P>
concept PermutationProblem = requires(const P& p, std::uint32_t i, std::uint32_t j,
                                      std::span<const std::uint32_t> tour) {
  { p.size() } -> std::convertible_to<std::size_t>;
  { p.distance(i, j) } -> std::convertible_to<double>;
  { p.candidates(i) } -> std::convertible_to<std::span<const std::uint32_t>>;
  { p.cost(tour) } -> std::convertible_to<double>;
};

/// Optional heuristic; the default is eta_ij = 1 / (d_ij + 0.1) as in eq. (1) and ACOTSP.
template <class P>
concept PermutationProblemWithHeuristic = PermutationProblem<P> &&
    requires(const P& p, std::uint32_t i, std::uint32_t j) {
  { p.heuristic(i, j) } -> std::convertible_to<double>;
};

/// Optional: an exact nearest-unvisited search for the construction fallback, faster than the
/// engine's O(n) scan (e.g. a spatial grid). One search object per ant:
///   s = p.make_nearest_search();  s.reset();  s.remove(node);  s.nearest(from)
/// where nearest(from) must return the unvisited node with the smallest distance(from, j),
/// lowest id on ties -- the same node the scan would pick.
template <class P>
concept PermutationProblemWithNearestSearch = PermutationProblem<P> && requires(const P& p) {
  p.make_nearest_search();
} && requires(decltype(std::declval<const P&>().make_nearest_search()) s, std::uint32_t i) {
  s.reset();
  s.remove(i);
  { s.nearest(i) } -> std::convertible_to<std::uint32_t>;
};

}  // namespace antslam::aco
