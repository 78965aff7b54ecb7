#pragma once
// SIGINT, SIGTERM and SIGHUP never leave temporary files behind. handle_interrupts() blocks
// them in every thread and lets one watcher thread wait for them; on a signal it removes every
// registered temporary path, prints one line and ends the process by the same signal (exit
// status 128 + signal number). Work that must not be cut in half (moving a command's outputs
// into place) runs inside without_interrupts(), which the watcher waits for.
//
// A command that can stop at a safe point and keep what it found holds a StopOnInterrupt while
// it works: the first signal then only requests a stop on its token (the engine's Termination::
// stop), the command writes its results marked partial and throws Interrupted, and the program
// ends with status 128 + signal number and one line saying what was kept. A second signal ends
// the process at once, as without a StopOnInterrupt.
//
// SIGKILL cannot be caught: what a killed run leaves (directories named
// ".antslam-staging.<pid>") is removed by the next run that writes beside it (output_files.hpp).

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <stop_token>
#include <string>

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

/// While one lives, the first interrupt requests a stop on token() instead of ending the
/// process (above). At most one lives at a time.
class StopOnInterrupt {
 public:
  StopOnInterrupt();
  ~StopOnInterrupt();
  StopOnInterrupt(const StopOnInterrupt&) = delete;
  StopOnInterrupt& operator=(const StopOnInterrupt&) = delete;

  std::stop_token token() const { return source_.get_token(); }
  /// The signal that requested the stop; 0 while none did.
  int signal() const;

 private:
  std::stop_source source_;
};

/// "SIGINT", "SIGTERM", "SIGHUP", else "signal N".
std::string signal_name(int signal);

/// A command stopped by an interrupt after writing what it kept: what() is one line,
/// "interrupted (<signal's name>); <kept>", and the program exits with 128 + signal.
class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal, const std::string& kept);
  int signal() const { return signal_; }
  /// What was kept (the line without its "interrupted (...); " start).
  const std::string& kept() const { return kept_; }

 private:
  int signal_;
  std::string kept_;
};

}  // namespace antslam::io
