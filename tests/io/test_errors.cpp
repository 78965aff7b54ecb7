// The error boundary (io/errors.hpp): one printable line per failure, the exit status of its
// kind, and a library's anonymous message placed in the context of its input file.

#include <gtest/gtest.h>

#include <filesystem>
#include <new>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "antslam/io/errors.hpp"

namespace antslam::cli {
namespace {

template <class E>
io::Failure failure(const E& error) {
  return io::failure_of(std::make_exception_ptr(error));
}

TEST(Errors, OneLineKeepsTextAndEscapesTheRest) {
  EXPECT_EQ(io::one_line("x.tsp:9: NODE_COORD_SECTION has 3 of 5 nodes"),
            "x.tsp:9: NODE_COORD_SECTION has 3 of 5 nodes");
  EXPECT_EQ(io::one_line("Terminating:\n  Residual and\tJacobian \r\nfailed.\n"),
            "Terminating: Residual and Jacobian failed.");
  EXPECT_EQ(io::one_line("bad byte \xff and \x01 here"), "bad byte \\xFF and \\x01 here");
  EXPECT_EQ(io::one_line("caf\xc3\xa9 \xe2\x82\xac"), "caf\xc3\xa9 \xe2\x82\xac");  // UTF-8 stays
  EXPECT_EQ(io::one_line("cut \xe2\x82"), "cut \\xE2\\x82");
}

TEST(Errors, EachKindHasItsExitStatus) {
  EXPECT_EQ(failure(io::UsageError("--trials: '-1'")).status, io::ExitStatus::usage);
  EXPECT_EQ(failure(std::invalid_argument("rho must be in (0, 1]")).status, io::ExitStatus::usage);
  EXPECT_EQ(failure(std::runtime_error("x.g2o:3: not a number")).status, io::ExitStatus::input);
  EXPECT_EQ(failure(io::InputError("x")).status, io::ExitStatus::input);
  EXPECT_EQ(failure(io::OutputError("out: disk full")).status, io::ExitStatus::runtime);
  const io::Failure memory = failure(std::bad_alloc());
  EXPECT_EQ(memory.status, io::ExitStatus::runtime);
  EXPECT_EQ(memory.message, "out of memory");
  const io::Failure internal = failure(std::logic_error("the best tour's length differs"));
  EXPECT_EQ(internal.status, io::ExitStatus::runtime);
  EXPECT_EQ(internal.message, "internal error: the best tour's length differs");
  const io::Failure fs = failure(std::filesystem::filesystem_error(
      "cannot create directories", "out/x", std::make_error_code(std::errc::not_a_directory)));
  EXPECT_EQ(fs.status, io::ExitStatus::runtime);
  EXPECT_EQ(fs.message, "out/x: Not a directory");
}

std::string in_context(const std::exception_ptr& error, io::ExitStatus& status) {
  try {
    io::in_context_of(std::vector<std::filesystem::path>{"log.clf", "ref.tum"},
                      [&] { std::rethrow_exception(error); });
  } catch (...) {
    const io::Failure f = io::failure_of(std::current_exception());
    status = f.status;
    return f.message;
  }
  return "";
}

TEST(Errors, InputContextNamesTheFileOnce) {
  io::ExitStatus status = io::ExitStatus::ok;
  EXPECT_EQ(
      in_context(std::make_exception_ptr(std::invalid_argument("moment_match: no weight")), status),
      "log.clf: moment_match: no weight");
  EXPECT_EQ(status, io::ExitStatus::input);
  EXPECT_EQ(
      in_context(std::make_exception_ptr(std::runtime_error("ref.tum:3: timestamp decreases")),
                 status),
      "ref.tum:3: timestamp decreases");
  EXPECT_EQ(status, io::ExitStatus::input);
  EXPECT_EQ(in_context(std::make_exception_ptr(io::UsageError("--fov: 400")), status),
            "--fov: 400");
  EXPECT_EQ(status, io::ExitStatus::usage);
  EXPECT_EQ(in_context(std::make_exception_ptr(std::bad_alloc()), status), "out of memory");
  EXPECT_EQ(status, io::ExitStatus::runtime);
  EXPECT_EQ(in_context(std::make_exception_ptr(std::logic_error("bug")), status),
            "internal error: bug");
}

}  // namespace
}  // namespace antslam::cli
