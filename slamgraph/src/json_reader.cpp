#include "json_reader.hpp"

#include <cmath>
#include <stdexcept>

namespace antslam::slam::detail {

namespace {

/// nlohmann's message without its "[json.exception.parse_error.101] " prefix.
std::string plain_message(const nlohmann::json::exception& e) {
  std::string what = e.what();
  const auto bracket = what.find("] ");
  if (what.starts_with("[json.exception") && bracket != std::string::npos)
    what = what.substr(bracket + 2);
  return what;
}

/// A key as JSON writes it, without the quotes: control characters escaped (a key may hold
/// "\n"), so that a message naming it stays one line.
std::string printable_key(const std::string& key) {
  const std::string quoted =
      nlohmann::json(key).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return quoted.substr(1, quoted.size() - 2);
}

}  // namespace

nlohmann::json parse_json(std::string_view text, const std::string& source) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // nlohmann's message names the line and column.
    throw std::runtime_error(source + ": JSON syntax error: " + plain_message(e));
  } catch (const nlohmann::json::exception& e) {
    // e.g. a number too large for a double ("number overflow parsing '1e400'").
    throw std::runtime_error(source + ": JSON: " + plain_message(e));
  }
}

void JsonField::fail(const std::string& problem) const {
  throw std::runtime_error(*source_ + ": " + (path_.empty() ? "" : path_ + ": ") + problem);
}

bool JsonField::has(const char* key) const { return value_->is_object() && value_->contains(key); }

JsonField JsonField::at(const char* key) const {
  if (!value_->is_object()) fail("expected an object");
  const auto it = value_->find(key);
  const std::string path = path_.empty() ? key : path_ + "." + key;
  if (it == value_->end()) JsonField(*value_, *source_, path).fail("missing");
  return {*it, *source_, path};
}

JsonField JsonField::item(std::size_t index) const {
  return {value_->at(index), *source_, path_ + "[" + std::to_string(index) + "]"};
}

void JsonField::only(std::initializer_list<const char*> allowed) const {
  only(std::span<const char* const>(allowed.begin(), allowed.size()));
}

void JsonField::only(std::span<const char* const> allowed) const {
  if (!value_->is_object()) fail("expected an object");
  for (const auto& [key, unused] : value_->items()) {
    bool known = false;
    for (const char* a : allowed) known |= key == a;
    if (!known) fail("unknown field '" + printable_key(key) + "'");
  }
}

std::size_t JsonField::array_size(std::size_t expected) const {
  if (!value_->is_array()) fail("expected an array");
  if (expected > 0 && value_->size() != expected)
    fail("expected " + std::to_string(expected) + " elements, got " +
         std::to_string(value_->size()));
  return value_->size();
}

double JsonField::number() const {
  if (!value_->is_number()) fail("expected a number");
  const double v = value_->get<double>();
  if (!std::isfinite(v)) fail("number is not finite");
  return v;
}

std::uint64_t JsonField::integer() const {
  if (!value_->is_number_unsigned()) fail("expected a non-negative integer");
  return value_->get<std::uint64_t>();
}

bool JsonField::boolean() const {
  if (!value_->is_boolean()) fail("expected true or false");
  return value_->get<bool>();
}

std::string JsonField::string() const {
  if (!value_->is_string()) fail("expected a string");
  return value_->get<std::string>();
}

Pose2 JsonField::pose() const {
  if (!value_->is_array() || value_->size() != 3) fail("expected [x, y, theta]");
  return Pose2::from_vector({item(0U).number(), item(1U).number(), item(2U).number()});
}

Gaussian2 JsonField::gaussian() const {
  only({"mean", "covariance"});
  const Pose2 mean = at("mean").pose();
  const JsonField cov = at("covariance");
  cov.array_size(3);
  Eigen::Matrix3d sigma;
  for (std::size_t r = 0; r < 3; ++r) {
    const JsonField row = cov.item(r);
    row.array_size(3);
    for (std::size_t c = 0; c < 3; ++c)
      sigma(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = row.item(c).number();
  }
  try {
    return Gaussian2(mean, sigma);
  } catch (const std::invalid_argument& e) {
    cov.fail(e.what());
  }
}

void check_header(const JsonField& root, std::string_view format, std::uint64_t max_version) {
  if (!root.json().is_object()) root.fail("expected a JSON object");
  const JsonField f = root.at("format");
  if (f.string() != format) f.fail("expected \"" + std::string(format) + "\"");
  const JsonField v = root.at("version");
  const std::uint64_t version = v.integer();
  if (version < 1 || version > max_version)
    v.fail(std::to_string(version) + " is not supported (this build reads versions 1 to " +
           std::to_string(max_version) + ")");
}

}  // namespace antslam::slam::detail
