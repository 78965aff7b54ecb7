#pragma once
// Line-oriented lexing shared by the TSPLIB instance and tour readers: lines with numbers for
// error messages, "KEY : VALUE" splitting, strict number parsing.

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <istream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace antslam::tsp::detail {

inline std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

inline std::vector<std::string_view> split(std::string_view s) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < s.size() && s[i] != ' ' && s[i] != '\t' && s[i] != '\r') ++i;
    if (i > start) tokens.push_back(s.substr(start, i - start));
  }
  return tokens;
}

/// A whole token as a double (nan/inf parse, so that callers can report them as non-finite).
inline std::optional<double> parse_double(std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  double value = 0.0;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ec != std::errc() || ptr != end || token.empty()) return std::nullopt;
  return value;
}

/// A whole token as an integer (decimal, optional sign).
inline std::optional<std::int64_t> parse_integer(std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  std::int64_t value = 0;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ec != std::errc() || ptr != end || token.empty()) return std::nullopt;
  return value;
}

/// Reads non-blank lines and names them in errors as "source:line: problem".
class LineReader {
 public:
  LineReader(std::istream& in, std::string source) : in_(in), source_(std::move(source)) {}

  /// Next non-blank line (trimmed); false at the end of the input.
  bool next(std::string_view& line) {
    while (std::getline(in_, text_)) {
      ++line_;
      line = trim(text_);
      if (!line.empty()) return true;
    }
    if (in_.bad()) throw std::runtime_error(source_ + ": read error");
    return false;
  }
  std::size_t line() const { return line_; }
  const std::string& source() const { return source_; }

  [[noreturn]] void fail(const std::string& problem) const {
    throw std::runtime_error(source_ + ":" + std::to_string(line_) + ": " + problem);
  }
  [[noreturn]] void fail_file(const std::string& problem) const {
    throw std::runtime_error(source_ + ": " + problem);
  }

 private:
  std::istream& in_;
  std::string source_;
  std::string text_;
  std::size_t line_ = 0;
};

/// A specification line "KEY : VALUE" (the colon may lack spaces or, for section keywords,
/// be absent). Returns the upper-case-as-written key and the trimmed value.
struct KeyValue {
  std::string_view key;
  std::string_view value;
};
inline KeyValue split_key_value(std::string_view line) {
  const auto colon = line.find(':');
  if (colon == std::string_view::npos) {
    const auto space = line.find_first_of(" \t");
    if (space == std::string_view::npos) return {line, {}};
    return {trim(line.substr(0, space)), trim(line.substr(space))};
  }
  return {trim(line.substr(0, colon)), trim(line.substr(colon + 1))};
}

/// True when the line starts a keyword rather than data (data lines start with a number).
inline bool looks_like_keyword(std::string_view line) {
  return !line.empty() && ((line.front() >= 'A' && line.front() <= 'Z') ||
                           (line.front() >= 'a' && line.front() <= 'z'));
}

}  // namespace antslam::tsp::detail
