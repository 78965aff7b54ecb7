#pragma once
// Whitespace-separated tokens of a text stream, with the line each comes from, for error
// messages "source:line: problem".

#include <algorithm>
#include <cstddef>
#include <istream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace antslam::qap::detail {

class TokenReader {
 public:
  TokenReader(std::istream& in, std::string source) : in_(in), source_(std::move(source)) {}

  /// The next token; false at the end of the input (line() is then the last line).
  bool next(std::string_view& token) {
    for (;;) {
      const std::size_t begin = text_.find_first_not_of(kSpace, position_);
      if (begin != std::string::npos) {
        const std::size_t end = std::min(text_.find_first_of(kSpace, begin), text_.size());
        token = std::string_view(text_).substr(begin, end - begin);
        position_ = end;
        return true;
      }
      if (!std::getline(in_, text_)) {
        if (in_.bad()) throw std::runtime_error(source_ + ": read error");
        text_.clear();
        return false;
      }
      ++line_;
      position_ = 0;
    }
  }

  /// Throws "source:line: problem" (line 1 for an empty input).
  [[noreturn]] void fail(const std::string& problem) const {
    throw std::runtime_error(source_ + ":" + std::to_string(std::max<std::size_t>(line_, 1)) +
                             ": " + problem);
  }

 private:
  static constexpr const char* kSpace = " \t\r\f\v";
  std::istream& in_;
  std::string source_;
  std::string text_;
  std::size_t position_ = 0;
  std::size_t line_ = 0;
};

}  // namespace antslam::qap::detail
