// Every numeric option of every antslam command refuses nonsense at parse time, before any
// work: "nan", infinities, a number that overflows a double, text; for counts also a negative
// value (it would wrap to 2^64 - 1), one above 2^64 - 1 (CLI11 would saturate it), a fraction.

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "commands.hpp"
#include "validators.hpp"

namespace antslam::cli {
namespace {

bool starts_with(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

/// What parsing `command option value` does: "refused" (a CLI11 validation or conversion error
/// naming the option), or what happened instead.
std::string outcome(const std::string& command, const std::string& option,
                    const std::string& value) {
  CLI::App app;
  add_commands(app);
  std::vector<std::string> args = {value, option, command};  // CLI11 takes them in reverse
  try {
    app.parse(args);
    return "accepted";
  } catch (const CLI::ValidationError& e) {
    return std::string(e.what()).find(option) != std::string::npos ? "refused"
                                                                   : "message without option";
  } catch (const CLI::ConversionError& e) {
    return "refused";
  } catch (const CLI::Error& e) {
    return std::string("accepted, then: ") + e.what();
  }
}

TEST(CliOptions, EveryNumericOptionRefusesNonsense) {
  CLI::App probe;
  add_commands(probe);
  std::vector<std::string> accepted;
  std::size_t numeric = 0;
  for (const CLI::App* command : probe.get_subcommands([](const CLI::App*) { return true; })) {
    for (const CLI::Option* option : command->get_options()) {
      if (option->get_lnames().empty() && option->get_snames().empty()) continue;  // positional
      if (option->get_group().empty()) continue;  // a hidden alias (CLI11 gives it no name)
      const std::string type = option->get_type_name();
      const bool is_unsigned = starts_with(type, "UINT");
      const bool is_integer = is_unsigned || starts_with(type, "INT");
      if (!is_integer && !starts_with(type, "FLOAT")) continue;
      ++numeric;
      std::vector<std::string> values = {"nan", "1e400", "twelve"};
      if (is_integer) values.insert(values.end(), {"18446744073709551616", "2.5"});
      if (is_unsigned) values.push_back("-1");
      if (!is_integer) values.insert(values.end(), {"inf", "-inf"});
      const std::string name = option->get_name();
      for (const std::string& value : values) {
        const std::string result = outcome(command->get_name(), name, value);
        if (result != "refused")
          accepted.push_back(command->get_name() + " " + name + " " + value + ": " + result);
      }
    }
  }
  EXPECT_GT(numeric, 80U);  // the check above saw the options (about a hundred)
  EXPECT_TRUE(accepted.empty()) << ::testing::PrintToString(accepted);
}

TEST(CliOptions, CountsAreReadInDecimal) {
  // CLI11 alone reads "010" as octal 8 and "0x10" as 16: a count is decimal digits only, and
  // the validator hands CLI11 the plain decimal text.
  std::string text = "010";
  EXPECT_EQ(count_in(0, 100)(text), "");
  EXPECT_EQ(text, "10");
  for (std::string bad : {"0x10", "+3", "-0", "1.5", "", "101"})
    EXPECT_NE(count_in(0, 100)(bad), "") << bad;
  std::string top = "18446744073709551615";
  EXPECT_EQ(non_negative_integer()(top), "");
}

TEST(CliOptions, NumbersMustBeFiniteAndInRange) {
  for (std::string good : {"0", "0.5", "1", "1e-3"}) EXPECT_EQ(finite_in(0.0, 1.0)(good), "");
  for (std::string bad : {"nan", "inf", "-inf", "1e400", "1.5", "-0.1", "x", "0.5x"})
    EXPECT_NE(finite_in(0.0, 1.0)(bad), "") << bad;
}

}  // namespace
}  // namespace antslam::cli
