#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "antslam/io/atomic_file.hpp"

namespace antslam::cli {
namespace {

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(AtomicFile, WritesAndReplaces) {
  const std::filesystem::path dir = std::filesystem::path(ANTSLAM_TEST_TMP) / "atomic";
  std::filesystem::remove_all(dir);
  const auto file = dir / "sub" / "out.txt";
  io::write_atomically(file, "first");
  EXPECT_EQ(read(file), "first");
  io::write_atomically(file, [](std::ostream& out) { out << "second"; });
  EXPECT_EQ(read(file), "second");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(file.parent_path()), {}), 1);
}

TEST(AtomicFile, FailedWriterLeavesTheOldFileAndNoTemporary) {
  const std::filesystem::path dir = std::filesystem::path(ANTSLAM_TEST_TMP) / "atomic_fail";
  std::filesystem::remove_all(dir);
  const auto file = dir / "out.txt";
  io::write_atomically(file, "old");
  EXPECT_THROW(io::write_atomically(file,
                                    [](std::ostream& out) {
                                      out << "half";
                                      throw std::runtime_error("interrupted");
                                    }),
               std::runtime_error);
  EXPECT_EQ(read(file), "old");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
}

}  // namespace
}  // namespace antslam::cli
