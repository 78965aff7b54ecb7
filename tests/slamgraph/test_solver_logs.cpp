// Ceres reports through glog: antslam keeps those messages off stderr unless --verbose
// (show_solver_logs), so that a failure is the one line its error names (a Ceres run once
// printed 35 lines of glog output). glog without InitGoogleLogging writes every message to
// stderr, as it does in the antslam program.

#include <glog/logging.h>
#include <gtest/gtest.h>

#include <string>

#include "antslam/slamgraph/ceres_baseline.hpp"

namespace antslam::slam {
namespace {

std::string stderr_of_an_error_message() {
  ::testing::internal::CaptureStderr();
  LOG(ERROR) << "a solver's diagnostic";
  return ::testing::internal::GetCapturedStderr();
}

// Ends as glog starts: shown.
TEST(SolverLogs, QuietUnlessShown) {
  show_solver_logs(false);
  EXPECT_EQ(stderr_of_an_error_message(), "");
  show_solver_logs(true);
  EXPECT_NE(stderr_of_an_error_message().find("a solver's diagnostic"), std::string::npos);
}

}  // namespace
}  // namespace antslam::slam
