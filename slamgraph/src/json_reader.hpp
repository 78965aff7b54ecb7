#pragma once
// Reading JSON documents field by field: every error names the file, the field path (e.g.
// `fragments[3].alignment.covariance`) and the problem, in one line.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>

#include "antslam/slamgraph/gaussian2.hpp"
#include "antslam/slamgraph/pose2.hpp"

namespace antslam::slam::detail {

/// Parses text; a syntax error becomes std::runtime_error "source: JSON syntax error ...".
nlohmann::json parse_json(std::string_view text, const std::string& source);

class JsonField {
 public:
  JsonField(const nlohmann::json& value, const std::string& source, std::string path)
      : value_(&value), source_(&source), path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& problem) const;

  const nlohmann::json& json() const { return *value_; }
  const std::string& path() const { return path_; }
  bool has(const char* key) const;
  /// A required member of an object.
  JsonField at(const char* key) const;
  /// An element of an array.
  JsonField item(std::size_t index) const;
  /// Fails if the object has members other than `allowed`.
  void only(std::initializer_list<const char*> allowed) const;
  void only(std::span<const char* const> allowed) const;
  /// Number of elements; fails unless an array (of `expected` elements if given).
  std::size_t array_size(std::size_t expected = 0) const;

  double number() const;
  std::uint64_t integer() const;
  std::string string() const;
  bool boolean() const;
  /// [x, y, theta] with finite numbers.
  Pose2 pose() const;
  /// {"mean": [x, y, theta], "covariance": [[3], [3], [3]]}, symmetric positive definite.
  Gaussian2 gaussian() const;

 private:
  const nlohmann::json* value_;
  const std::string* source_;
  std::string path_;
};

/// Checks "format" and "version" of a document: version must be in [1, max_version].
void check_header(const JsonField& root, std::string_view format, std::uint64_t max_version);

}  // namespace antslam::slam::detail
