#include "backend_option.hpp"

#include <stdexcept>
#include <vector>

namespace antslam::cli {

void add_backend_option(CLI::App& command, std::string& name) {
  std::vector<std::string> names;
  std::string help = "backend running the ants in parallel:";
  for (const aco::BackendInfo& b : aco::kBackends) {
    names.emplace_back(b.name);
    help += " " + std::string(b.name) + " (" + std::string(b.summary) + ")";
  }
  command.add_option("--backend", name, help)->check(CLI::IsMember(names))->capture_default_str();
}

aco::BackendKind parse_backend_option(const std::string& name) {
  const auto kind = aco::parse_backend(name);
  if (!kind)
    throw std::invalid_argument("--backend: unknown backend '" + name + "' (expected one of " +
                                aco::backend_names() + ")");
  return *kind;
}

}  // namespace antslam::cli
