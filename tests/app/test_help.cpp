// The program's help text and its "did you mean" suggestions (app/help_format.hpp,
// app/suggestions.hpp).

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "help_format.hpp"
#include "suggestions.hpp"

namespace antslam::cli {
namespace {

TEST(WrapWords, BreaksBetweenWordsAndKeepsLineBreaks) {
  EXPECT_EQ(wrap_words("aa bb cc dd", 5), "aa bb\ncc dd");
  EXPECT_EQ(wrap_words("aa bb\ncc", 80), "aa bb\ncc");
  EXPECT_EQ(wrap_words("a verylongword b", 4), "a\nverylongword\nb");
  EXPECT_EQ(wrap_words("", 10), "");
  EXPECT_EQ(wrap_words("Example:\n  aa bb cc", 7), "Example:\n  aa bb\n  cc");
}

TEST(EditDistance, CountsEditsAndSwaps) {
  EXPECT_EQ(edit_distance("--varient", "--variant"), 1u);
  EXPECT_EQ(edit_distance("abc", "acb"), 1u);  // a transposition of neighbours
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("same", "same"), 0u);
}

TEST(Closest, OnlyNamesCloseEnoughToBeATypo) {
  const std::vector<std::string> names = {"--variant", "--iterations", "--instance"};
  EXPECT_EQ(closest("--varient", names), "--variant");
  EXPECT_EQ(closest("--instnace", names), "--instance");
  EXPECT_FALSE(closest("--colour", names).has_value());
  EXPECT_FALSE(closest("-x", names).has_value());
}

/// The program's parser, as main() builds it.
struct Program {
  CLI::App app{"antslam"};
  Program() {
    app.formatter(std::make_shared<WrappingFormatter>());
    add_commands(app);
  }
  /// The parse error's message with its suggestion; "" if the line parses.
  std::string error_of(std::vector<std::string> args) {
    std::reverse(args.begin(), args.end());  // CLI11 takes the arguments in reverse order
    try {
      app.parse(args);
    } catch (const CLI::ParseError& e) {
      return e.what() + did_you_mean(app);
    }
    return "";
  }
};

TEST(DidYouMean, SuggestsTheOptionOfTheCommand) {
  Program program;
  const std::string error = program.error_of({"tsp", "--varient", "mmas"});
  EXPECT_NE(error.find("(unknown --varient: did you mean --variant?)"), std::string::npos) << error;
}

TEST(DidYouMean, SuggestsACommand) {
  Program program;
  const std::string error = program.error_of({"robsut", "x.g2o"});
  EXPECT_NE(error.find("(unknown robsut: did you mean robust?)"), std::string::npos) << error;
}

TEST(DidYouMean, SaysNothingWithoutACloseName) {
  Program program;
  const std::string error = program.error_of({"tsp", "--zzzzzzzz"});
  EXPECT_EQ(error.find("did you mean"), std::string::npos) << error;
}

TEST(Help, EveryCommandFitsTheWidthAndHasAnExample) {
  Program program;
  for (const CLI::App* command : program.app.get_subcommands({})) {
    const std::string help = command->help();
    std::istringstream lines(help);
    std::string line;
    while (std::getline(lines, line))
      EXPECT_LE(line.size(), kHelpWidth) << command->get_name() << ": " << line;
    EXPECT_NE(help.find("Example:\n  "), std::string::npos) << command->get_name();
  }
}

}  // namespace
}  // namespace antslam::cli
