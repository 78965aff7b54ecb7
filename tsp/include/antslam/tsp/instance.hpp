#pragma once
// A symmetric TSP instance as TSPLIB defines it (Reinelt, "TSPLIB 95", 1995): node coordinates
// with an edge-weight function, or an explicit weight matrix. Distances are TSPLIB's integers
// with the official rounding of each type (see distance.hpp).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "antslam/tsp/distance.hpp"

namespace antslam::tsp {

enum class EdgeWeightType { euc_2d, ceil_2d, att, geo, explicit_matrix };

std::string_view to_string(EdgeWeightType type);
/// TSPLIB keyword (EUC_2D, CEIL_2D, ATT, GEO, EXPLICIT) to type.
std::optional<EdgeWeightType> parse_edge_weight_type(std::string_view keyword);

/// Coordinates spanning more than this (in either axis) would overflow TSPLIB's integer
/// distances; the readers reject them.
inline constexpr double kMaxCoordinateSpan = 1.0e9;

class Instance {
 public:
  Instance() = default;
  /// A coordinate instance (EUC_2D, CEIL_2D, ATT or GEO). Throws std::invalid_argument on a
  /// non-finite coordinate, a span above kMaxCoordinateSpan, or fewer than 3 nodes.
  Instance(std::string name, EdgeWeightType type, std::vector<Point> coords);
  /// An EXPLICIT instance from a full symmetric n x n matrix (row-major). Throws
  /// std::invalid_argument on a wrong size, an asymmetric or negative entry, or n < 3.
  Instance(std::string name, std::size_t n, std::vector<std::int32_t> weights);

  std::size_t size() const { return n_; }
  const std::string& name() const { return name_; }
  EdgeWeightType type() const { return type_; }
  bool has_coordinates() const { return type_ != EdgeWeightType::explicit_matrix; }
  /// Node coordinates; for EXPLICIT instances the optional display coordinates (or empty).
  const std::vector<Point>& coords() const { return coords_; }
  /// EXPLICIT only: the full symmetric matrix, row-major.
  const std::vector<std::int32_t>& weights() const { return weights_; }

  std::string comment;  ///< free text (TSPLIB COMMENT)

  /// Attaches display coordinates (TSPLIB DISPLAY_DATA_SECTION) to an EXPLICIT instance.
  void set_display_coords(std::vector<Point> coords);

  /// TSPLIB distance between nodes i and j (0-based), an integer.
  double distance(std::uint32_t i, std::uint32_t j) const {
    switch (type_) {
      case EdgeWeightType::euc_2d:
        return distance::euc_2d(coords_[i], coords_[j]);
      case EdgeWeightType::ceil_2d:
        return distance::ceil_2d(coords_[i], coords_[j]);
      case EdgeWeightType::att:
        return distance::att(coords_[i], coords_[j]);
      case EdgeWeightType::geo:
        return distance::geo(geo_radians_[i], geo_radians_[j]);
      case EdgeWeightType::explicit_matrix:
        break;
    }
    return weights_[std::size_t{i} * n_ + j];
  }

  /// For coordinate instances: the smallest TSPLIB distance of any pair at least `euclidean`
  /// apart in plain coordinates (the rounding is monotone). Lets spatial searches stop early.
  double distance_lower_bound(double euclidean) const;

  /// Length of the closed tour (0-based node ids), exact.
  double tour_length(std::span<const std::uint32_t> tour) const;

 private:
  std::string name_;
  EdgeWeightType type_ = EdgeWeightType::euc_2d;
  std::size_t n_ = 0;
  std::vector<Point> coords_;
  std::vector<Point> geo_radians_;  ///< GEO: (latitude, longitude) in radians
  std::vector<std::int32_t> weights_;
};

}  // namespace antslam::tsp
