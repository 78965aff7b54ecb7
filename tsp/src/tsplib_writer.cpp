// TSPLIB instance and tour writers.

#include <charconv>
#include <ostream>

#include "antslam/tsp/tsplib.hpp"

namespace antslam::tsp {

namespace {

/// Shortest text that reads back as the same double.
std::string number(double v) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, ec == std::errc() ? end : buffer);
}

void write_points(std::ostream& out, const std::vector<Point>& points) {
  for (std::size_t i = 0; i < points.size(); ++i)
    out << i + 1 << ' ' << number(points[i].x) << ' ' << number(points[i].y) << '\n';
}

}  // namespace

void write_instance(std::ostream& out, const Instance& instance) {
  const std::size_t n = instance.size();
  out << "NAME : " << instance.name() << '\n';
  if (!instance.comment.empty()) out << "COMMENT : " << instance.comment << '\n';
  out << "TYPE : TSP\nDIMENSION : " << n << "\nEDGE_WEIGHT_TYPE : " << to_string(instance.type())
      << '\n';
  if (instance.has_coordinates()) {
    out << "NODE_COORD_SECTION\n";
    write_points(out, instance.coords());
  } else {
    out << "EDGE_WEIGHT_FORMAT : FULL_MATRIX\nEDGE_WEIGHT_SECTION\n";
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j)
        out << (j == 0 ? "" : " ") << instance.weights()[i * n + j];
      out << '\n';
    }
    if (!instance.coords().empty()) {
      out << "DISPLAY_DATA_SECTION\n";
      write_points(out, instance.coords());
    }
  }
  out << "EOF\n";
}

void write_tour(std::ostream& out, std::string_view name, std::span<const std::uint32_t> tour,
                std::string_view comment) {
  out << "NAME : " << name << '\n';
  if (!comment.empty()) out << "COMMENT : " << comment << '\n';
  out << "TYPE : TOUR\nDIMENSION : " << tour.size() << "\nTOUR_SECTION\n";
  for (std::uint32_t city : tour) out << city + 1 << '\n';
  out << "-1\nEOF\n";
}

}  // namespace antslam::tsp
