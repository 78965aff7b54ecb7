#pragma once
// Results are written atomically: to a temporary file beside the target, flushed to disk, then
// renamed over it. An interrupted run leaves either the old file or the new one, never half.

#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

namespace antslam::cli {

/// Calls writer(stream) on a temporary file and renames it to `path` (creating parent
/// directories). Throws std::runtime_error naming the file if anything fails.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& writer);

/// The same for content already in memory (e.g. an encoded PNG).
void write_atomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace antslam::cli
