#pragma once
// A layered-choice problem given as tables, for research problems written in Python: one option
// per layer, cost(c) = sum_l unary[l][c_l] + sum_l pairwise[l][c_l][c_{l+1}] + term(c), with an
// optional heuristic table eta[l][o] (1 when none, as in eq. (11)). It satisfies
// aco::LayeredProblemWithHeuristic, so every variant and backend runs on it. The engine deposits
// q / cost, so tables and term are >= 0 (adding a constant to every entry of a layer does not
// change which choice is best).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace antslam::python {

class TableProblem {
 public:
  /// The user's term of the whole choice (>= 0); called from the ants' threads.
  using Term = std::function<double(std::span<const std::uint32_t> choice)>;

  /// unary[l]: the costs of layer l's options; pairwise: empty, or one row-major
  /// unary[l].size() x unary[l + 1].size() table per consecutive pair; heuristic: empty, or one
  /// row per layer of unary's shape. Throws std::invalid_argument naming the table and entry
  /// for a wrong shape, a non-finite or negative cost or heuristic, or a layer without options.
  TableProblem(std::vector<std::vector<double>> unary, std::vector<std::vector<double>> pairwise,
               std::vector<std::vector<double>> heuristic, Term term = {});

  std::size_t layer_count() const { return unary_.size(); }
  std::size_t option_count(std::size_t layer) const { return unary_[layer].size(); }
  double heuristic(std::size_t layer, std::size_t option) const {
    return heuristic_.empty() ? 1.0 : heuristic_[layer][option];
  }
  double cost(std::span<const std::uint32_t> choice) const;

 private:
  std::vector<std::vector<double>> unary_;
  std::vector<std::vector<double>> pairwise_;
  std::vector<std::vector<double>> heuristic_;
  Term term_;
};

}  // namespace antslam::python
