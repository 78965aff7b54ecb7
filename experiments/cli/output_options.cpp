#include "output_options.hpp"

#include "cli/errors.hpp"

namespace antslam::cli {

void require_output(bool given, std::string_view name) {
  if (!given) throw UsageError(std::string(name) + " is required");
}

}  // namespace antslam::cli
