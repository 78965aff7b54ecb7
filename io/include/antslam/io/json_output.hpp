#pragma once
// JSON result files as the readers expect them: no "null" where a number belongs and no
// exception in the middle of writing.

#include <nlohmann/json.hpp>
#include <string>

namespace antslam::io {

/// The document as JSON text (two-space indent, newline at the end), an object with the member
/// "antslam_version" (the version that wrote it) added. Bytes of a string that are
/// not UTF-8 (a file name, a TSPLIB NAME) become U+FFFD; a number that is not finite (JSON
/// would write null) throws std::logic_error naming its field, as an internal error: the
/// readers reject non-finite input, so no result should hold one.
std::string json_text(const nlohmann::json& doc);

}  // namespace antslam::io
