#include "help_format.hpp"

#include <algorithm>
#include <sstream>
#include <string>

namespace antslam::cli {

namespace {
/// The width of the option column (CLI11's default is 30).
constexpr std::size_t kNameColumn = 30;
/// Room for a description beside the option column.
constexpr std::size_t kDescriptionWidth = kHelpWidth - kNameColumn;
}  // namespace

namespace {

/// One line of text (no '\n') wrapped into lines of at most `width` characters, each continued
/// line indented as the first.
void wrap_line(std::string_view line, std::size_t width, std::string& out) {
  const std::size_t indent = std::min(line.find_first_not_of(' '), line.size());
  const std::size_t room = width > indent ? width - indent : 1;
  std::size_t line_length = 0;
  std::size_t i = indent;
  out.append(indent, ' ');
  while (i < line.size()) {
    if (line[i] == ' ') {
      ++i;
      continue;
    }
    const std::size_t end = std::min(line.find(' ', i), line.size());
    const std::string_view word = line.substr(i, end - i);
    if (line_length > 0 && line_length + 1 + word.size() > room) {
      out += '\n';
      out.append(indent, ' ');
      line_length = 0;
    } else if (line_length > 0) {
      out += ' ';
      ++line_length;
    }
    out += word;
    line_length += word.size();
    i = end;
  }
}

}  // namespace

std::string wrap_words(std::string_view text, std::size_t width) {
  std::string out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    wrap_line(text.substr(start, end - start), width, out);
    if (end == text.size()) break;
    out += '\n';
    start = end + 1;
  }
  return out;
}

WrappingFormatter::WrappingFormatter() { column_width(kNameColumn); }

std::string WrappingFormatter::make_option_desc(const CLI::Option* option) const {
  return wrap_words(CLI::Formatter::make_option_desc(option), kDescriptionWidth);
}

std::string WrappingFormatter::make_description(const CLI::App* app) const {
  return wrap_words(CLI::Formatter::make_description(app), kHelpWidth);
}

std::string WrappingFormatter::make_subcommand(const CLI::App* sub) const {
  std::stringstream out;
  CLI::detail::format_help(out, sub->get_display_name(true),
                           wrap_words(sub->get_description(), kDescriptionWidth), column_width_);
  return out.str();
}

}  // namespace antslam::cli
