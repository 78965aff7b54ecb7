#include "antslam/eval/relations.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::eval {

namespace {

constexpr const char* kFormat = "expected 8 numbers `t1 t2 dx dy dz droll dpitch dyaw`";

[[noreturn]] void fail(const std::string& source, std::size_t line, const std::string& problem) {
  throw std::runtime_error(source + ":" + std::to_string(line) + ": " + problem);
}

/// The line's 8 numbers, or a failure naming source and line.
std::array<double, 8> parse_fields(const std::string& text, const std::string& source,
                                   std::size_t line) {
  std::istringstream fields(text);
  std::array<double, 8> v{};
  std::string token;
  for (double& x : v) {
    if (!(fields >> token)) fail(source, line, kFormat);
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, x);  // nan/inf parse, rejected below
    if (ec != std::errc() || ptr != end) fail(source, line, kFormat);
    if (!std::isfinite(x)) fail(source, line, "non-finite number '" + token + "'");
  }
  if (fields >> token) fail(source, line, "unexpected extra field '" + token + "'");
  return v;
}

}  // namespace

std::vector<Relation> read_relations(std::istream& in, const std::string& source) {
  std::vector<Relation> relations;
  std::string text;
  std::size_t line = 0;
  while (std::getline(in, text)) {
    ++line;
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos || text[first] == '#') continue;
    const auto [t1, t2, dx, dy, dz, droll, dpitch, dyaw] = parse_fields(text, source, line);
    if (dz != 0.0 || droll != 0.0 || dpitch != 0.0)
      fail(source, line, "dz, droll and dpitch must be 0 in a 2D relation");
    const auto check = [&](double value, const char* what, double limit, const char* unit) {
      if (std::abs(value) <= limit) return;
      std::ostringstream problem;
      problem << what << " " << value << " " << unit << " is beyond " << limit << " " << unit;
      fail(source, line, problem.str());
    };
    check(t1, "t1", slam::kMaxTimestamp, "s");
    check(t2, "t2", slam::kMaxTimestamp, "s");
    check(dx, "dx", slam::kMaxCoordinate, "m");
    check(dy, "dy", slam::kMaxCoordinate, "m");
    relations.push_back({t1, t2, slam::Pose2{dx, dy, slam::wrap_angle(dyaw)}, line});
  }
  if (in.bad()) throw std::runtime_error(source + ": read error");
  if (relations.empty()) throw std::runtime_error(source + ": no relations");
  return relations;
}

std::vector<Relation> read_relations_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw std::runtime_error(path.string() + ": is a directory, expected a relations file");
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  return read_relations(in, path.string());
}

}  // namespace antslam::eval
