#pragma once
// One result file written atomically: an OutputFiles transaction of one file (output_files.hpp):
// checked (no directory, symbolic link or FIFO at the path), written beside it, flushed to disk,
// then renamed over it. An interrupted run leaves either the old file or the new one, never
// half, and no temporary file. Commands with several outputs declare them all in one
// OutputFiles up front instead.

#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

namespace antslam::io {

/// Calls writer(stream) on a temporary file and renames it to `path` (creating parent
/// directories). Throws UsageError for an unusable path, OutputError naming the file if writing
/// fails.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& writer);

/// The same for content already in memory (e.g. an encoded PNG).
void write_atomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace antslam::io
