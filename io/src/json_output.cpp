#include "antslam/io/json_output.hpp"

#include <cmath>
#include <stdexcept>

#include "antslam/version.hpp"

namespace antslam::io {

namespace {

void check_finite(const nlohmann::json& value, const std::string& path) {
  if (value.is_number_float() && !std::isfinite(value.get<double>()))
    throw std::logic_error("result field " + (path.empty() ? "(root)" : path) + " is not finite");
  if (value.is_object())
    for (const auto& [key, item] : value.items())
      check_finite(item, path.empty() ? key : path + "." + key);
  if (value.is_array())
    for (std::size_t i = 0; i < value.size(); ++i)
      check_finite(value[i], path + "[" + std::to_string(i) + "]");
}

}  // namespace

std::string json_text(const nlohmann::json& doc) {
  check_finite(doc, "");
  nlohmann::json stamped = doc;
  if (stamped.is_object()) stamped["antslam_version"] = kVersion;
  return stamped.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace antslam::io
