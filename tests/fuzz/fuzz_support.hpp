#pragma once
// What every reader's harness checks on any input (docs/fuzzing.md): the reader either returns,
// or throws std::runtime_error / std::invalid_argument whose message names the source ("fuzz")
// on one line. Anything else -- another exception, a message without the source, a crash, a
// hang, a sanitizer report -- is a finding: the harness aborts and libFuzzer keeps the input.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace antslam::fuzz {

/// The name every harness gives its input; error messages must start with it.
inline constexpr std::string_view kSource = "fuzz";

inline std::string text_of(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

[[noreturn]] inline void finding(const char* what, const std::string& detail) {
  std::fprintf(stderr, "finding: %s: %s\n", what, detail.c_str());
  std::abort();
}

/// Aborts unless `condition` holds (a property of a successful read).
inline void require(bool condition, const char* property) {
  if (!condition) finding("property violated", property);
}

/// Runs read(); returns whether it succeeded. A refusal must be the one-line kind.
template <class F>
bool reads(F&& read) {
  try {
    read();
    return true;
  } catch (const std::runtime_error& e) {
    const std::string_view message = e.what();
    if (!message.starts_with(kSource) || message.find('\n') != std::string_view::npos)
      finding("runtime_error without the source on one line", e.what());
  } catch (const std::invalid_argument& e) {
    const std::string_view message = e.what();
    if (!message.starts_with(kSource) || message.find('\n') != std::string_view::npos)
      finding("invalid_argument without the source on one line", e.what());
  }
  return false;
}

/// The reader's result written with write(out, value) and read back with
/// read(in, "fuzz-written"); aborts unless the writer takes it and the reader reads it back.
template <class T, class Write, class Read>
T written_and_read_back(const T& value, Write&& write, Read&& read) {
  std::stringstream written;
  require(reads([&] { write(written, value); }), "the writer takes what the reader gives");
  T back{};
  require(reads([&] { back = read(written, "fuzz-written"); }), "the writer's output reads back");
  return back;
}

}  // namespace antslam::fuzz
