#pragma once
// Reading line-based text formats (TUM trajectories, g2o graphs, pose lists): one error line
// "source:line: problem" for anything malformed.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <istream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace antslam::slam::detail {

[[noreturn]] inline void fail_at(const std::string& source, std::size_t line,
                                 const std::string& problem) {
  throw std::runtime_error(source + ":" + std::to_string(line) + ": " + problem);
}

/// Opens an input file; throws std::runtime_error "path: is a directory" or "path: cannot open"
/// (a directory would open, and fail only on the first read with the library's own words).
std::ifstream open_input(const std::filesystem::path& path);

/// Whole-token number, accepting nan/inf so that they can be reported as non-finite.
bool parse_number(const std::string& token, double& value);

/// Whole-token non-negative integer (an id or an index).
bool parse_index(const std::string& token, std::uint64_t& value);

/// Calls f(fields, line) for every line that is neither blank nor a '#' comment; throws
/// "source: read error" if the stream fails.
template <class F>
void for_each_data_line(std::istream& in, const std::string& source, F&& f) {
  std::string text;
  std::size_t line = 0;
  while (std::getline(in, text)) {
    ++line;
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos || text[first] == '#') continue;
    std::istringstream fields(text);
    f(fields, line);
  }
  if (in.bad()) throw std::runtime_error(source + ": read error");
}

}  // namespace antslam::slam::detail
