// TSPLIB tour reader (TYPE TOUR, TOUR_SECTION ended by -1).

#include <fstream>
#include <stdexcept>

#include "antslam/tsp/tsplib.hpp"
#include "tsplib_lexer.hpp"

namespace antslam::tsp {

std::vector<std::uint32_t> parse_tour(std::istream& in, const std::string& source, std::size_t n) {
  detail::LineReader r(in, source);
  std::vector<std::uint32_t> tour;
  std::vector<bool> seen(n, false);
  bool have_section = false;
  bool section_open = false;
  std::string_view line;
  while (r.next(line)) {
    if (section_open && !detail::looks_like_keyword(line)) {
      for (std::string_view token : detail::split(line)) {
        if (!section_open) r.fail("data after the tour's closing -1");
        const auto id = detail::parse_integer(token);
        if (!id) r.fail("node id '" + std::string(token) + "' is not an integer");
        if (*id == -1) {
          section_open = false;
          continue;
        }
        if (*id < 1 || static_cast<std::uint64_t>(*id) > n)
          r.fail("node id " + std::to_string(*id) + " is not in 1.." + std::to_string(n));
        if (seen[static_cast<std::size_t>(*id - 1)])
          r.fail("node " + std::to_string(*id) + " appears twice");
        seen[static_cast<std::size_t>(*id - 1)] = true;
        tour.push_back(static_cast<std::uint32_t>(*id - 1));
      }
      continue;
    }
    section_open = false;
    const auto [key, value] = detail::split_key_value(line);
    if (key == "EOF") break;
    if (key == "NAME" || key == "COMMENT") continue;
    if (key == "TYPE") {
      if (value != "TOUR") r.fail("TYPE " + std::string(value) + ": not a tour file");
    } else if (key == "DIMENSION") {
      const auto d = detail::parse_integer(value);
      if (!d || *d < 0 || static_cast<std::uint64_t>(*d) != n)
        r.fail("DIMENSION " + std::string(value) + " does not match the instance's " +
               std::to_string(n) + " nodes");
    } else if (key == "TOUR_SECTION") {
      if (have_section) r.fail("TOUR_SECTION given twice");
      have_section = section_open = true;
    } else {
      r.fail("unexpected '" + std::string(key) + "' in a tour file");
    }
  }
  if (!have_section) r.fail_file("missing TOUR_SECTION");
  if (tour.size() != n)
    r.fail_file("TOUR_SECTION has " + std::to_string(tour.size()) + " of " + std::to_string(n) +
                " nodes");
  return tour;
}

std::vector<std::uint32_t> read_tour(const std::filesystem::path& path, std::size_t n) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw std::runtime_error(path.string() + ": is a directory, expected a TSPLIB file");
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  return parse_tour(in, path.string(), n);
}

}  // namespace antslam::tsp
