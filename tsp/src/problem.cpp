#include "antslam/tsp/problem.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "antslam/tsp/neighbours.hpp"

namespace antslam::tsp {

namespace {

/// The grid serves instances whose distance grows with plain Euclidean distance.
bool grid_applies(EdgeWeightType type) {
  return type == EdgeWeightType::euc_2d || type == EdgeWeightType::ceil_2d ||
         type == EdgeWeightType::att;
}

}  // namespace

TspProblem::TspProblem(Instance instance, const ProblemSettings& settings)
    : instance_(std::make_shared<const Instance>(std::move(instance))), n_(instance_->size()) {
  if (settings.candidates == 0 || settings.ls_neighbours == 0)
    throw std::invalid_argument("candidate and neighbour lists need at least one entry");
  candidates_ = std::min(settings.candidates, n_ - 1);
  ls_neighbours_ = std::min(settings.ls_neighbours, n_ - 1);
  width_ = std::max(candidates_, ls_neighbours_);
  if (grid_applies(instance_->type()))
    grid_ = std::make_shared<const SpatialGrid>(instance_->coords());
  neighbours_ = nearest_neighbours(*instance_, width_, grid_.get());
  neighbour_distance_.resize(neighbours_.size());
  for (std::size_t e = 0; e < neighbours_.size(); ++e)
    neighbour_distance_[e] =
        instance_->distance(static_cast<std::uint32_t>(e / width_), neighbours_[e]);
  if (n_ <= settings.matrix_limit) {
    constexpr double kMaxMatrixBytes = 8.0 * (1 << 30);
    const double bytes = 4.0 * static_cast<double>(n_) * static_cast<double>(n_);
    if (bytes > kMaxMatrixBytes)
      throw std::invalid_argument("a distance matrix of " + std::to_string(n_) + " cities needs " +
                                  std::to_string(static_cast<long>(bytes / (1 << 30))) +
                                  " GiB; lower the matrix limit (at most 46000 cities)");
    matrix_.resize(n_ * n_);
    for (std::uint32_t i = 0; i < n_; ++i)
      for (std::uint32_t j = 0; j < n_; ++j)
        matrix_[std::size_t{i} * n_ + j] =
            i == j ? 0 : static_cast<std::int32_t>(instance_->distance(i, j));
  }
}

double TspProblem::cost(std::span<const std::uint32_t> tour) const {
  double length = 0.0;
  for (std::size_t s = 0; s + 1 < tour.size(); ++s) length += distance(tour[s], tour[s + 1]);
  return tour.empty() ? 0.0 : length + distance(tour.back(), tour.front());
}

std::size_t TspProblem::memory_bytes() const {
  std::size_t bytes = matrix_.size() * sizeof(std::int32_t) +
                      neighbours_.size() * (sizeof(std::uint32_t) + sizeof(double));
  if (grid_) bytes += (grid_->cell_count() + 1) * sizeof(std::uint32_t) + n_ * 3 * sizeof(int);
  return bytes;
}

}  // namespace antslam::tsp
