#include "output_options.hpp"

#include "antslam/io/errors.hpp"

namespace antslam::cli {

void require_output(bool given, std::string_view name) {
  if (!given) throw io::UsageError(std::string(name) + " is required");
}

}  // namespace antslam::cli
