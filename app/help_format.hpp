#pragma once
// The program's help: descriptions wrapped so that every line fits kHelpWidth columns, and an
// example command line under each command's help.

#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>
#include <string_view>

namespace antslam::cli {

inline constexpr std::size_t kHelpWidth = 100;  ///< columns of a help line, at most

/// `text` with its words wrapped into lines of at most `width` characters, joined by '\n'
/// (existing line breaks kept; a word longer than `width` stands on its own line).
std::string wrap_words(std::string_view text, std::size_t width);

/// CLI11's formatter, with option, command and program descriptions wrapped to kHelpWidth (the
/// footer, an example command line, is shown as it is).
class WrappingFormatter : public CLI::Formatter {
 public:
  WrappingFormatter();
  std::string make_option_desc(const CLI::Option* option) const override;
  std::string make_description(const CLI::App* app) const override;
  std::string make_subcommand(const CLI::App* sub) const override;
};

}  // namespace antslam::cli
