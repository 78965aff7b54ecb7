#pragma once
// TSPLIB's distance functions with their official rounding (Reinelt, "TSPLIB 95", Sec. 2).
// All return an integer value as a double (exact: TSPLIB distances fit in 32 bits).

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace antslam::tsp {

struct Point {
  double x = 0.0;  ///< first coordinate (GEO: latitude as DDD.MM)
  double y = 0.0;  ///< second coordinate (GEO: longitude as DDD.MM)
};

}  // namespace antslam::tsp

namespace antslam::tsp::distance {

/// floor(x) for 0 <= x < 2^31 by truncation, which compiles to two instructions on every
/// x86-64 (std::floor needs SSE4.1 for that). Distances stay below 2^31: coordinates span at
/// most kMaxCoordinateSpan.
inline double floor_nonnegative(double x) {
  return static_cast<double>(static_cast<std::int32_t>(x));
}

/// TSPLIB's nint(x) = (int)(x + 0.5) for x >= 0.
inline double nint(double x) { return floor_nonnegative(x + 0.5); }

inline double euclidean(Point a, Point b) {
  const double dx = a.x - b.x;
  const double dy = a.y - b.y;
  return std::sqrt(dx * dx + dy * dy);
}

/// EUC_2D: Euclidean distance rounded to the nearest integer.
inline double euc_2d(Point a, Point b) { return nint(euclidean(a, b)); }

/// CEIL_2D: Euclidean distance rounded up.
inline double ceil_2d(Point a, Point b) {
  const double e = euclidean(a, b);
  const double t = floor_nonnegative(e);
  return t < e ? t + 1.0 : t;
}

/// ATT pseudo-Euclidean distance: r = sqrt((dx^2 + dy^2) / 10), rounded up.
inline double att_from_r(double r) {
  const double t = nint(r);
  return t < r ? t + 1.0 : t;
}
inline double att(Point a, Point b) {
  const double dx = a.x - b.x;
  const double dy = a.y - b.y;
  return att_from_r(std::sqrt((dx * dx + dy * dy) / 10.0));
}

/// GEO: a coordinate DDD.MM (degrees, minutes) to radians. TSPLIB's text writes nint() for the
/// degrees, but its reference code and every published optimum use truncation, as here.
inline double geo_radians(double ddd_mm) {
  constexpr double kPi = 3.141592;  // sic: TSPLIB's value
  const double degrees = std::trunc(ddd_mm);
  const double minutes = ddd_mm - degrees;
  return kPi * (degrees + 5.0 * minutes / 3.0) / 180.0;
}

/// GEO: great-circle distance in km on TSPLIB's idealised sphere, a and b in radians
/// (latitude, longitude), truncated after adding 1.
inline double geo(Point a, Point b) {
  constexpr double kRadius = 6378.388;
  const double q1 = std::cos(a.y - b.y);
  const double q2 = std::cos(a.x - b.x);
  const double q3 = std::cos(a.x + b.x);
  const double c = std::clamp(0.5 * ((1.0 + q1) * q2 - (1.0 - q1) * q3), -1.0, 1.0);
  return std::floor(kRadius * std::acos(c) + 1.0);
}

}  // namespace antslam::tsp::distance
