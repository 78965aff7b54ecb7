#include "suggestions.hpp"

#include <algorithm>
#include <numeric>

namespace antslam::cli {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Optimal string alignment distance, three rows of the dynamic programme.
  std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
  std::iota(previous.begin(), previous.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    before.swap(previous);
    previous.swap(current);
  }
  return previous[b.size()];
}

std::optional<std::string> closest(std::string_view typed, const std::vector<std::string>& names) {
  const std::size_t allowed = std::clamp<std::size_t>(typed.size() / 3, 1, 3);
  std::optional<std::string> best;
  std::size_t best_distance = allowed + 1;
  for (const std::string& name : names) {
    const std::size_t d = edit_distance(typed, name);
    if (d < best_distance) {
      best = name;
      best_distance = d;
    }
  }
  return best;
}

namespace {

/// Every spelling of the options of `app` ("--variant", "-o", ...).
std::vector<std::string> option_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& n : option->get_lnames()) names.push_back("--" + n);
    for (const std::string& n : option->get_snames()) names.push_back("-" + n);
  }
  return names;
}

/// The most deeply selected command of the command line.
const CLI::App& command_of(const CLI::App& app) {
  const CLI::App* at = &app;
  while (!at->get_subcommands().empty()) at = at->get_subcommands().front();
  return *at;
}

}  // namespace

std::string did_you_mean(const CLI::App& app) {
  const CLI::App& command = command_of(app);
  std::vector<std::string> options = option_names(command);
  if (&command != &app) {
    const std::vector<std::string> global = option_names(app);
    options.insert(options.end(), global.begin(), global.end());
  }
  std::vector<std::string> commands;
  if (&command == &app)
    for (const CLI::App* sub : app.get_subcommands({})) commands.push_back(sub->get_name());
  std::vector<std::string> left = command.remaining();
  if (&command != &app) {
    const std::vector<std::string> root_left = app.remaining();
    left.insert(left.end(), root_left.begin(), root_left.end());
  }
  for (const std::string& arg : left) {
    const bool is_option = arg.size() > 1 && arg[0] == '-';
    const std::string typed = is_option ? arg.substr(0, arg.find('=')) : arg;
    if (const auto match = closest(typed, is_option ? options : commands))
      return " (unknown " + typed + ": did you mean " + *match + "?)";
  }
  return {};
}

}  // namespace antslam::cli
