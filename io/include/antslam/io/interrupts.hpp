#pragma once
// SIGINT, SIGTERM and SIGHUP never leave temporary files behind. handle_interrupts() blocks
// them in every thread and lets one watcher thread wait for them; on a signal it removes every
// registered temporary path, prints one line and ends the process by the same signal (exit
// status 128 + signal number). Work that must not be cut in half (moving a command's outputs
// into place) runs inside without_interrupts(), which the watcher waits for.
//
// SIGKILL cannot be caught: what a killed run leaves (directories named
// ".antslam-staging.<pid>") is removed by the next run that writes beside it (output_files.hpp).

#include <filesystem>
#include <functional>

namespace antslam::io {

/// Starts the watcher. Call once, first thing in main(), before any other thread starts
/// (threads inherit the blocked signals, so that only the watcher receives them).
void handle_interrupts();

/// Runs create() and registers `path` for removal on an interrupt, both while interrupts wait
/// (so that an interrupt cannot fall between creating the path and registering it).
void create_temporary(const std::filesystem::path& path, const std::function<void()>& create);

/// Removes `path` (recursively) and forgets it, while interrupts wait.
void remove_temporary(const std::filesystem::path& path);

/// Runs f() with interrupts held back: one arriving meanwhile takes effect when f() returns.
void without_interrupts(const std::function<void()>& f);

}  // namespace antslam::io
