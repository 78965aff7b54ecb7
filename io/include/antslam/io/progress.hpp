#pragma once
// A live one-line progress display on stderr, shown only when stderr is a terminal (quiet when
// piped or redirected), redrawn at most 10 times a second.

#include <chrono>
#include <string>
#include <string_view>

namespace antslam::io {

bool stderr_is_terminal();

class Progress {
 public:
  explicit Progress(bool enabled = stderr_is_terminal());
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  bool enabled() const { return enabled_; }
  /// Redraws the line if enough time passed since the last redraw (or `force`).
  void update(std::string_view text, bool force = false);
  /// Clears the line so that normal output can follow.
  void clear();

 private:
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace antslam::io
