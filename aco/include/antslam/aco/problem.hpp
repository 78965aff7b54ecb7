#pragma once
// The concepts of the engine's three built-in problem families. A problem plugs in by satisfying
// one of them (its family then registers through aco::family_of, family.hpp) or by naming a
// family of its own through that trait; the engine never sees anything else of it. Every family
// minimises a cost that must be a number
// >= 0 (+infinity allowed): the colony refuses a NaN or a negative cost with std::invalid_argument.

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

/// Subset-selection problem: the ant starts from the empty set and adds one element at a time,
/// chosen among the candidates compatible with every element already taken, until no
/// candidate is left; so every solution is a maximal set of pairwise compatible elements
/// (a maximal clique when compatible(i, j) is adjacency, a maximal independent set when it is
/// non-adjacency, a maximal packing for a conflict graph). compatible(i, j) must be symmetric;
/// the cost is a function of the set (the elements in the order they were added).
template <class P>
concept SubsetProblem = requires(const P& p, std::uint32_t i, std::uint32_t j,
                                 std::span<const std::uint32_t> subset) {
  { p.element_count() } -> std::convertible_to<std::size_t>;
  { p.compatible(i, j) } -> std::convertible_to<bool>;
  { p.cost(subset) } -> std::convertible_to<double>;
};

/// Optional static heuristic desirability eta >= 0 of an element (1 when the problem gives none).
template <class P>
concept SubsetProblemWithHeuristic = SubsetProblem<P> && requires(const P& p, std::uint32_t i) {
  { p.heuristic(i) } -> std::convertible_to<double>;
};

}  // namespace antslam::aco
