#include "table_problem.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace antslam::python {

namespace {

void check_entries(const std::vector<double>& row, const std::string& name) {
  for (std::size_t k = 0; k < row.size(); ++k)
    if (!std::isfinite(row[k]) || row[k] < 0.0)
      throw std::invalid_argument(name + "[" + std::to_string(k) + "] = " + std::to_string(row[k]) +
                                  " is not a finite number >= 0");
}

}  // namespace

TableProblem::TableProblem(std::vector<std::vector<double>> unary,
                           std::vector<std::vector<double>> pairwise,
                           std::vector<std::vector<double>> heuristic, Term term)
    : unary_(std::move(unary)),
      pairwise_(std::move(pairwise)),
      heuristic_(std::move(heuristic)),
      term_(std::move(term)) {
  if (unary_.empty()) throw std::invalid_argument("costs: no layers");
  for (std::size_t l = 0; l < unary_.size(); ++l) {
    const std::string name = "costs[" + std::to_string(l) + "]";
    if (unary_[l].empty()) throw std::invalid_argument(name + ": a layer without options");
    check_entries(unary_[l], name);
  }
  if (!pairwise_.empty()) {
    if (pairwise_.size() + 1 != unary_.size())
      throw std::invalid_argument("pairwise: " + std::to_string(pairwise_.size()) + " tables for " +
                                  std::to_string(unary_.size()) +
                                  " layers (expected one per consecutive pair)");
    for (std::size_t l = 0; l < pairwise_.size(); ++l) {
      const std::string name = "pairwise[" + std::to_string(l) + "]";
      if (pairwise_[l].size() != unary_[l].size() * unary_[l + 1].size())
        throw std::invalid_argument(name + ": expected " + std::to_string(unary_[l].size()) +
                                    " x " + std::to_string(unary_[l + 1].size()) + " entries");
      check_entries(pairwise_[l], name);
    }
  }
  if (!heuristic_.empty()) {
    if (heuristic_.size() != unary_.size())
      throw std::invalid_argument("heuristic: expected one row per layer");
    for (std::size_t l = 0; l < heuristic_.size(); ++l) {
      const std::string name = "heuristic[" + std::to_string(l) + "]";
      if (heuristic_[l].size() != unary_[l].size())
        throw std::invalid_argument(name + ": expected " + std::to_string(unary_[l].size()) +
                                    " entries, one per option");
      check_entries(heuristic_[l], name);
    }
  }
}

double TableProblem::cost(std::span<const std::uint32_t> choice) const {
  double total = 0.0;
  for (std::size_t l = 0; l < unary_.size(); ++l) total += unary_[l][choice[l]];
  for (std::size_t l = 0; l < pairwise_.size(); ++l)
    total += pairwise_[l][choice[l] * unary_[l + 1].size() + choice[l + 1]];
  if (term_) total += term_(choice);
  return total;
}

}  // namespace antslam::python
