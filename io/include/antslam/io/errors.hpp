#pragma once
// The error boundary of the antslam program: every failure becomes one line
// "antslam: error: <file>[:<line>]: <problem>" on stderr and an exit status that says what kind
// of failure it was (README, "Exit status").
//
//   status  kind     what
//   0       -        success
//   1       input    an input file is missing, unreadable or malformed, or its data cannot be
//                    processed (std::runtime_error, InputError)
//   2       usage    a nonsense command line: unknown option, value out of range, conflicting
//                    options, an unusable output path (CLI11 errors, std::invalid_argument,
//                    UsageError)
//   3       runtime  the run could not finish: out of memory, outputs could not be written,
//                    an internal error (std::bad_alloc, OutputError, anything else)
//   130/143 -        interrupted by SIGINT/SIGTERM (the process ends by the signal; temporary
//                    files are removed first, interrupts.hpp), or a command that stopped at a
//                    safe point and wrote what it kept, marked partial (Interrupted: the line
//                    is "antslam: interrupted (<signal>); <what was kept>")

#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace antslam::io {

enum class ExitStatus : int { ok = 0, input = 1, usage = 2, runtime = 3 };

/// A nonsense command line (exit status 2).
class UsageError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// An input file that cannot be read or used (exit status 1).
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Outputs that cannot be written (exit status 3).
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One failure as the program reports it.
struct Failure {
  std::string message;  ///< one line, without the "antslam: error: " prefix
  ExitStatus status = ExitStatus::runtime;
  int signal = 0;  ///< an interrupted command (Interrupted): the signal; the exit is 128 + it
};

/// The failure an exception stands for (call inside a catch block or with a captured pointer).
Failure failure_of(const std::exception_ptr& error);

/// The text as one printable line: line breaks and tabs become spaces (runs collapsed),
/// other control bytes and bytes that are not UTF-8 text become \xNN.
std::string one_line(std::string_view text);

/// Runs f() on the data of input files (the first is the main one): a failure
/// (std::runtime_error or std::invalid_argument) becomes an InputError, with "file: " in front
/// unless the message names one of the files already, so that a library's anonymous message
/// says which input it is about. UsageError, OutputError, std::bad_alloc and internal errors
/// (other std::logic_error) pass unchanged.
template <class F>
decltype(auto) in_context_of(const std::vector<std::filesystem::path>& files, F&& f);
template <class F>
decltype(auto) in_context_of(const std::filesystem::path& file, F&& f) {
  return in_context_of(std::vector<std::filesystem::path>{file}, std::forward<F>(f));
}

namespace detail {
/// Rethrows the current exception as in_context_of says.
[[noreturn]] void rethrow_in_context(const std::vector<std::filesystem::path>& files);
}  // namespace detail

template <class F>
decltype(auto) in_context_of(const std::vector<std::filesystem::path>& files, F&& f) {
  try {
    return std::forward<F>(f)();
  } catch (...) {
    detail::rethrow_in_context(files);
  }
}

}  // namespace antslam::io
