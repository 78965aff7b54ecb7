#include "output_options.hpp"

#include <stdexcept>

namespace antslam::cli {

void require_output(bool given, std::string_view name) {
  if (!given) throw std::invalid_argument(std::string(name) + " is required");
}

}  // namespace antslam::cli
