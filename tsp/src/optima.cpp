#include "antslam/tsp/optima.hpp"

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tsplib_lexer.hpp"

namespace antslam::tsp {

std::optional<double> known_optimum(const std::filesystem::path& instance_path) {
  const std::filesystem::path csv = instance_path.parent_path() / "optima.csv";
  std::ifstream in(csv);
  if (!in) return std::nullopt;
  const std::string stem = instance_path.stem().string();
  std::string text;
  std::size_t line = 0;
  while (std::getline(in, text)) {
    ++line;
    const std::string_view row = detail::trim(text);
    if (line == 1 || row.empty()) continue;  // header
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    for (std::size_t comma; (comma = row.find(',', start)) != std::string_view::npos;
         start = comma + 1)
      fields.push_back(detail::trim(row.substr(start, comma - start)));
    fields.push_back(detail::trim(row.substr(start)));
    const auto fail = [&](const std::string& problem) {
      throw std::runtime_error(csv.string() + ":" + std::to_string(line) + ": " + problem);
    };
    if (fields.size() != 4) fail("expected 'instance,n,edge_weight_type,optimal_length'");
    if (fields[0] != stem) continue;
    const auto optimum = detail::parse_double(fields[3]);
    if (!optimum || !(*optimum > 0.0)) fail("optimal_length is not a positive number");
    return *optimum;
  }
  return std::nullopt;
}

}  // namespace antslam::tsp
