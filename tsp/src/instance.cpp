#include "antslam/tsp/instance.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace antslam::tsp {

std::string_view to_string(EdgeWeightType type) {
  switch (type) {
    case EdgeWeightType::euc_2d:
      return "EUC_2D";
    case EdgeWeightType::ceil_2d:
      return "CEIL_2D";
    case EdgeWeightType::att:
      return "ATT";
    case EdgeWeightType::geo:
      return "GEO";
    case EdgeWeightType::explicit_matrix:
      return "EXPLICIT";
  }
  return "?";
}

std::optional<EdgeWeightType> parse_edge_weight_type(std::string_view keyword) {
  for (EdgeWeightType t : {EdgeWeightType::euc_2d, EdgeWeightType::ceil_2d, EdgeWeightType::att,
                           EdgeWeightType::geo, EdgeWeightType::explicit_matrix})
    if (to_string(t) == keyword) return t;
  return std::nullopt;
}

namespace {

void require_nodes(std::size_t n) {
  if (n < 3)
    throw std::invalid_argument("a TSP instance needs at least 3 nodes, got " + std::to_string(n));
}

void check_coords(const std::vector<Point>& coords) {
  double lo_x = 0.0, hi_x = 0.0, lo_y = 0.0, hi_y = 0.0;
  for (std::size_t i = 0; i < coords.size(); ++i) {
    const Point p = coords[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw std::invalid_argument("node " + std::to_string(i + 1) + " has a non-finite coordinate");
    lo_x = i == 0 ? p.x : std::min(lo_x, p.x);
    hi_x = i == 0 ? p.x : std::max(hi_x, p.x);
    lo_y = i == 0 ? p.y : std::min(lo_y, p.y);
    hi_y = i == 0 ? p.y : std::max(hi_y, p.y);
  }
  if (hi_x - lo_x > kMaxCoordinateSpan || hi_y - lo_y > kMaxCoordinateSpan)
    throw std::invalid_argument("coordinates span more than 1e9: distances would overflow");
}

}  // namespace

Instance::Instance(std::string name, EdgeWeightType type, std::vector<Point> coords)
    : name_(std::move(name)), type_(type), n_(coords.size()), coords_(std::move(coords)) {
  if (type_ == EdgeWeightType::explicit_matrix)
    throw std::invalid_argument("EXPLICIT instances are built from a weight matrix");
  require_nodes(n_);
  check_coords(coords_);
  if (type_ == EdgeWeightType::geo) {
    geo_radians_.reserve(n_);
    for (std::size_t i = 0; i < n_; ++i) {
      const Point p = coords_[i];
      if (std::abs(p.x) > 90.0 || std::abs(p.y) > 180.0)
        throw std::invalid_argument("node " + std::to_string(i + 1) +
                                    ": GEO coordinates must be latitude/longitude in DDD.MM");
      geo_radians_.push_back({distance::geo_radians(p.x), distance::geo_radians(p.y)});
    }
  }
}

Instance::Instance(std::string name, std::size_t n, std::vector<std::int32_t> weights)
    : name_(std::move(name)),
      type_(EdgeWeightType::explicit_matrix),
      n_(n),
      weights_(std::move(weights)) {
  require_nodes(n_);
  if (weights_.size() != n_ * n_)
    throw std::invalid_argument("weight matrix has " + std::to_string(weights_.size()) +
                                " entries, expected " + std::to_string(n_ * n_));
  for (std::size_t i = 0; i < n_; ++i)
    for (std::size_t j = 0; j < n_; ++j) {
      const std::int32_t w = weights_[i * n_ + j];
      if (w < 0)
        throw std::invalid_argument("negative weight " + std::to_string(w) + " between nodes " +
                                    std::to_string(i + 1) + " and " + std::to_string(j + 1));
      if (w != weights_[j * n_ + i])
        throw std::invalid_argument("weight matrix is not symmetric between nodes " +
                                    std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                                    " (only the symmetric TSP is supported)");
    }
}

void Instance::set_display_coords(std::vector<Point> coords) {
  if (type_ != EdgeWeightType::explicit_matrix)
    throw std::invalid_argument("display coordinates belong to EXPLICIT instances");
  if (coords.size() != n_)
    throw std::invalid_argument("display data has " + std::to_string(coords.size()) +
                                " nodes, expected " + std::to_string(n_));
  check_coords(coords);
  coords_ = std::move(coords);
}

double Instance::distance_lower_bound(double euclidean) const {
  switch (type_) {
    case EdgeWeightType::euc_2d:
      return distance::nint(euclidean);
    case EdgeWeightType::ceil_2d:
      return std::ceil(euclidean);
    case EdgeWeightType::att:
      return distance::att_from_r(std::sqrt(euclidean * euclidean / 10.0));
    case EdgeWeightType::geo:
    case EdgeWeightType::explicit_matrix:
      break;
  }
  return 0.0;  // no relation to plain coordinates
}

double Instance::tour_length(std::span<const std::uint32_t> tour) const {
  double length = 0.0;
  for (std::size_t s = 0; s < tour.size(); ++s)
    length += distance(tour[s], tour[s + 1 == tour.size() ? 0 : s + 1]);
  return length;
}

}  // namespace antslam::tsp
