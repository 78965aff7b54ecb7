// TSPLIB instance reader. Every error names the file, the line and the problem.

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "antslam/tsp/tsplib.hpp"
#include "tsplib_lexer.hpp"

namespace antslam::tsp {

using detail::LineReader;

namespace {

constexpr std::array<std::string_view, 10> kSpecificationKeys = {"NAME",
                                                                 "TYPE",
                                                                 "COMMENT",
                                                                 "DIMENSION",
                                                                 "CAPACITY",
                                                                 "EDGE_WEIGHT_TYPE",
                                                                 "EDGE_WEIGHT_FORMAT",
                                                                 "EDGE_DATA_FORMAT",
                                                                 "NODE_COORD_TYPE",
                                                                 "DISPLAY_DATA_TYPE"};
constexpr std::array<std::string_view, 8> kSections = {
    "NODE_COORD_SECTION",  "DEPOT_SECTION",        "DEMAND_SECTION", "EDGE_DATA_SECTION",
    "FIXED_EDGES_SECTION", "DISPLAY_DATA_SECTION", "TOUR_SECTION",   "EDGE_WEIGHT_SECTION"};
constexpr std::size_t kMaxDimension = 10'000'000;

bool is_one_of(std::string_view key, std::span<const std::string_view> keys) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

/// A line that ends a data section: a keyword, a section name or EOF.
bool is_keyword_line(std::string_view line) {
  const std::string_view key = detail::split_key_value(line).key;
  return key == "EOF" || is_one_of(key, kSpecificationKeys) || is_one_of(key, kSections);
}

/// Which entries of the symmetric matrix an EXPLICIT section lists, row by row. The *_COL
/// forms list the transposed triangle, i.e. the opposite *_ROW form of a symmetric matrix.
enum class Layout { full, upper, lower, upper_diag, lower_diag, function };

std::optional<Layout> parse_layout(std::string_view s) {
  if (s == "FULL_MATRIX") return Layout::full;
  if (s == "UPPER_ROW" || s == "LOWER_COL") return Layout::upper;
  if (s == "LOWER_ROW" || s == "UPPER_COL") return Layout::lower;
  if (s == "UPPER_DIAG_ROW" || s == "LOWER_DIAG_COL") return Layout::upper_diag;
  if (s == "LOWER_DIAG_ROW" || s == "UPPER_DIAG_COL") return Layout::lower_diag;
  if (s == "FUNCTION") return Layout::function;
  return std::nullopt;
}

/// Column range [begin, end) of row i.
std::pair<std::size_t, std::size_t> row_range(Layout layout, std::size_t i, std::size_t n) {
  switch (layout) {
    case Layout::upper:
      return {i + 1, n};
    case Layout::lower:
      return {0, i};
    case Layout::upper_diag:
      return {i, n};
    case Layout::lower_diag:
      return {0, i + 1};
    case Layout::full:
    case Layout::function:
      break;
  }
  return {0, n};
}

std::size_t entry_count(Layout layout, std::size_t n) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto [b, e] = row_range(layout, i, n);
    count += e - b;
  }
  return count;
}

std::size_t parse_dimension(const LineReader& r, std::string_view value) {
  const auto d = detail::parse_integer(value);
  if (!d) r.fail("DIMENSION '" + std::string(value) + "' is not an integer");
  if (*d < 3) r.fail("DIMENSION " + std::to_string(*d) + ": a tour needs at least 3 nodes");
  if (static_cast<std::uint64_t>(*d) > kMaxDimension)
    r.fail("DIMENSION " + std::to_string(*d) + " is larger than " + std::to_string(kMaxDimension));
  return static_cast<std::size_t>(*d);
}

/// NODE_COORD_SECTION or DISPLAY_DATA_SECTION: n lines "id x y", ids 1..n each once. The
/// points are kept as read and placed at the end, so that memory follows the lines the section
/// has, not the DIMENSION it claims.
std::vector<Point> read_points(LineReader& r, std::size_t n, const std::string& section) {
  std::vector<std::pair<std::size_t, Point>> listed;
  std::vector<bool> seen(n, false);
  std::string_view line;
  for (std::size_t count = 0; count < n; ++count) {
    const std::string short_by =
        section + " has " + std::to_string(count) + " of " + std::to_string(n) + " nodes";
    if (!r.next(line)) r.fail(short_by + " (the file ends)");
    if (is_keyword_line(line)) r.fail(short_by);
    const auto tokens = detail::split(line);
    if (tokens.size() != 3) r.fail("expected 'id x y' in " + section);
    const auto id = detail::parse_integer(tokens[0]);
    if (!id || *id < 1 || static_cast<std::uint64_t>(*id) > n)
      r.fail("node id '" + std::string(tokens[0]) + "' is not in 1.." + std::to_string(n));
    const auto index = static_cast<std::size_t>(*id - 1);
    if (seen[index]) r.fail("node " + std::to_string(*id) + " appears twice");
    seen[index] = true;
    double xy[2];
    for (int c = 0; c < 2; ++c) {
      const std::string_view token = tokens[static_cast<std::size_t>(c) + 1];
      const auto v = detail::parse_double(token);
      if (!v) r.fail("coordinate '" + std::string(token) + "' is not a number");
      if (!std::isfinite(*v))
        r.fail("node " + std::to_string(*id) + " has a non-finite coordinate '" +
               std::string(token) + "'");
      xy[c] = *v;
    }
    listed.push_back({index, {xy[0], xy[1]}});
  }
  std::vector<Point> points(n);
  for (const auto& [index, point] : listed) points[index] = point;
  return points;
}

/// EDGE_WEIGHT_SECTION: the listed entries, any number per line, into a full n x n matrix. The
/// matrix is made only once every entry has been read, so that a DIMENSION the section does not
/// back with weights costs no memory.
std::vector<std::int32_t> read_weights(LineReader& r, std::size_t n, Layout layout) {
  const std::size_t total = entry_count(layout, n);
  std::vector<std::int32_t> listed;
  std::string_view line;
  while (listed.size() < total) {
    const std::string short_by = "EDGE_WEIGHT_SECTION has " + std::to_string(listed.size()) +
                                 " of " + std::to_string(total) + " weights";
    if (!r.next(line)) r.fail(short_by + " (the file ends)");
    if (is_keyword_line(line)) r.fail(short_by);
    for (std::string_view token : detail::split(line)) {
      if (listed.size() == total)
        r.fail("more weights than the " + std::to_string(total) + " expected");
      const auto v = detail::parse_double(token);
      if (!v) r.fail("weight '" + std::string(token) + "' is not a number");
      if (!std::isfinite(*v) || *v < 0.0 || *v != std::floor(*v) ||
          *v > std::numeric_limits<std::int32_t>::max())
        r.fail("weight '" + std::string(token) + "' is not a non-negative 32-bit integer");
      listed.push_back(static_cast<std::int32_t>(*v));
    }
  }
  std::vector<std::int32_t> w(n * n, 0);
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto [begin, end] = row_range(layout, i, n);
    for (std::size_t j = begin; j < end; ++j, ++k) {
      if (i == j) continue;  // TSPLIB files carry 0 or a large sentinel on the diagonal; unused
      w[i * n + j] = listed[k];
      if (layout != Layout::full) w[j * n + i] = listed[k];
    }
  }
  return w;
}

struct Specification {
  std::string name;
  std::string comment;
  std::optional<std::size_t> dimension;
  std::optional<EdgeWeightType> type;
  std::optional<Layout> layout;
  std::optional<std::vector<Point>> coords;
  std::optional<std::vector<Point>> display;
  std::optional<std::vector<std::int32_t>> weights;
  std::string last_section;  ///< the section read last, for messages about extra data
};

void read_keyword(LineReader& r, Specification& s, std::string_view key, std::string_view value) {
  const std::string k(key);
  const auto need_value = [&] {
    if (value.empty()) r.fail(k + " has no value");
  };
  const auto need_dimension = [&] {
    if (!s.dimension) r.fail(k + " before DIMENSION");
  };
  if (key == "NAME") {
    s.name = value;
  } else if (key == "COMMENT") {
    if (!s.comment.empty()) s.comment += ' ';
    s.comment += value;
  } else if (key == "TYPE") {
    need_value();
    if (value == "TOUR") r.fail("TYPE TOUR: this is a tour file, not an instance");
    if (value != "TSP") r.fail("TYPE " + std::string(value) + " is not supported (TSP only)");
  } else if (key == "DIMENSION") {
    if (s.dimension) r.fail("DIMENSION given twice");
    s.dimension = parse_dimension(r, value);
  } else if (key == "EDGE_WEIGHT_TYPE") {
    need_value();
    s.type = parse_edge_weight_type(value);
    if (!s.type)
      r.fail("EDGE_WEIGHT_TYPE " + std::string(value) +
             " is not supported (EUC_2D, CEIL_2D, ATT, GEO, EXPLICIT)");
  } else if (key == "EDGE_WEIGHT_FORMAT") {
    need_value();
    s.layout = parse_layout(value);
    if (!s.layout) r.fail("EDGE_WEIGHT_FORMAT " + std::string(value) + " is not supported");
  } else if (key == "NODE_COORD_TYPE") {
    if (value != "TWOD_COORDS" && value != "NO_COORDS")
      r.fail("NODE_COORD_TYPE " + std::string(value) + " is not supported (2D only)");
  } else if (key == "CAPACITY" || key == "EDGE_DATA_FORMAT" || key == "DISPLAY_DATA_TYPE") {
    // Not used by the TSP.
  } else if (key == "NODE_COORD_SECTION") {
    need_dimension();
    if (s.coords) r.fail("NODE_COORD_SECTION given twice");
    s.coords = read_points(r, *s.dimension, k);
  } else if (key == "DISPLAY_DATA_SECTION") {
    need_dimension();
    if (s.display) r.fail("DISPLAY_DATA_SECTION given twice");
    s.display = read_points(r, *s.dimension, k);
  } else if (key == "EDGE_WEIGHT_SECTION") {
    need_dimension();
    if (!s.layout || *s.layout == Layout::function)
      r.fail("EDGE_WEIGHT_SECTION needs an EDGE_WEIGHT_FORMAT matrix layout before it");
    if (s.weights) r.fail("EDGE_WEIGHT_SECTION given twice");
    s.weights = read_weights(r, *s.dimension, *s.layout);
  } else if (is_one_of(key, kSections)) {
    r.fail(k + " is not supported");
  } else if (!detail::looks_like_keyword(key)) {
    r.fail(s.last_section.empty() ? "data '" + k + "' outside a section"
                                  : s.last_section + " has more than the DIMENSION " +
                                        std::to_string(s.dimension.value_or(0)) + " entries");
  } else {
    r.fail("unknown keyword '" + k + "'");
  }
  if (is_one_of(k, kSections)) s.last_section = k;  // `key` may view a line read since
}

Instance build(const LineReader& r, Specification& s) {
  if (!s.dimension) r.fail_file("missing DIMENSION");
  if (!s.type) r.fail_file("missing EDGE_WEIGHT_TYPE");
  try {
    if (*s.type == EdgeWeightType::explicit_matrix) {
      if (!s.weights) r.fail_file("missing EDGE_WEIGHT_SECTION");
      Instance instance(s.name, *s.dimension, std::move(*s.weights));
      if (s.display || s.coords) instance.set_display_coords(s.display ? *s.display : *s.coords);
      instance.comment = s.comment;
      return instance;
    }
    if (!s.coords) r.fail_file("missing NODE_COORD_SECTION");
    Instance instance(s.name, *s.type, std::move(*s.coords));
    instance.comment = s.comment;
    return instance;
  } catch (const std::invalid_argument& e) {
    r.fail_file(e.what());
  }
}

}  // namespace

Instance parse_instance(std::istream& in, const std::string& source) {
  LineReader r(in, source);
  Specification s;
  std::string_view line;
  while (r.next(line)) {
    const auto [key, value] = detail::split_key_value(line);
    if (key == "EOF") break;
    read_keyword(r, s, key, value);
  }
  return build(r, s);
}

Instance read_instance(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw std::runtime_error(path.string() + ": is a directory, expected a TSPLIB file");
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  return parse_instance(in, path.string());
}

}  // namespace antslam::tsp
