// Output files as one transaction (io/output_files.hpp): checked when declared, untouched until
// commit, replaced together, stale outputs removed, nothing temporary left behind -- also after
// an interrupt (io/interrupts.hpp) or a killed run.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "antslam/io/errors.hpp"
#include "antslam/io/interrupts.hpp"
#include "antslam/io/output_files.hpp"

namespace antslam::cli {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(ANTSLAM_TEST_TMP) / "output_files" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void put(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

/// The names in a directory, sorted, space-separated.
std::string listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : " ") + n;
  return out;
}

std::string usage_error(const fs::path& path) {
  io::OutputFiles outputs;
  try {
    outputs.add(path);
  } catch (const io::UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(OutputFiles, RefusesUnusablePathsWhenDeclared) {
  const fs::path dir = fresh_dir("refuse");
  fs::create_directory(dir / "a-directory");
  put(dir / "a-file", "x");
  fs::create_symlink(dir / "a-file", dir / "a-link");
  ASSERT_EQ(::mkfifo((dir / "a-fifo").c_str(), 0600), 0);
  EXPECT_EQ(usage_error(dir / "a-directory"),
            (dir / "a-directory").string() + ": is a directory, expected a file");
  EXPECT_NE(usage_error(dir / "a-link").find("is a symbolic link"), std::string::npos);
  EXPECT_NE(usage_error(dir / "a-fifo").find("is not a regular file"), std::string::npos);
  EXPECT_NE(usage_error(dir / "a-file" / "out.json").find("a-file is not a directory"),
            std::string::npos);
  EXPECT_NE(usage_error(dir / "a-file" / "deeper" / "out.json").find("a-file is not a directory"),
            std::string::npos);
  EXPECT_EQ(usage_error(dir / "new" / "deeper" / "out.json"), "");  // made at the first write
  EXPECT_EQ(usage_error(""), ": the output path is empty");
  io::OutputFiles twice;
  twice.add(dir / "x.json");
  EXPECT_THROW(twice.add(dir / "." / "x.json"), io::UsageError);
  // Nothing was created or replaced by declaring.
  EXPECT_EQ(listing(dir), "a-directory a-fifo a-file a-link");
  EXPECT_EQ(read(dir / "a-file"), "x");
}

TEST(OutputFiles, RefusesADirectoryItCannotWrite) {
  if (::geteuid() == 0) GTEST_SKIP() << "root may write anywhere";
  const fs::path dir = fresh_dir("read-only");
  fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
  EXPECT_NE(usage_error(dir / "x.json").find("is not writable"), std::string::npos);
  fs::permissions(dir, fs::perms::owner_all);
}

TEST(OutputFiles, RefusesAParentTheFileSystemWillNotCreate) {
  // /proc takes no new directories, not even from root (whom access(2) lets write anywhere).
  const std::string problem = usage_error("/proc/antslam-missing/x.json");
  EXPECT_NE(problem.find("cannot create a directory in /proc"), std::string::npos) << problem;
  EXPECT_FALSE(fs::exists("/proc/antslam-missing"));
}

TEST(OutputFiles, LeavesNoProbeBehind) {
  const fs::path dir = fresh_dir("probe");
  io::OutputFiles outputs;
  outputs.add(dir / "sub" / "x.json");
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(OutputFiles, TouchesNothingUntilCommitAndLeavesNoTemporaryFiles) {
  const fs::path dir = fresh_dir("uncommitted");
  put(dir / "a.txt", "old a");
  {
    io::OutputFiles outputs;
    outputs.add(dir / "a.txt");
    outputs.add(dir / "sub" / "b.txt");
    outputs.write(dir / "a.txt", "new a");
    outputs.write(dir / "sub" / "b.txt", [](std::ostream& out) { out << "new b"; });
    EXPECT_EQ(read(dir / "a.txt"), "old a");
    EXPECT_FALSE(fs::exists(dir / "sub" / "b.txt"));
  }  // an exception unwinding past here looks the same
  EXPECT_EQ(read(dir / "a.txt"), "old a");
  EXPECT_EQ(listing(dir), "a.txt sub");
  EXPECT_EQ(listing(dir / "sub"), "");
}

TEST(OutputFiles, CommitReplacesTogetherAndRemovesStaleOutputs) {
  const fs::path dir = fresh_dir("commit");
  put(dir / "map.png", "map of an earlier run");
  put(dir / "report.json", "old report");
  put(dir / "notes.txt", "the user's own file");
  io::OutputFiles outputs;
  outputs.add(dir / "report.json");
  outputs.add(dir / "map.png");  // declared, but this run draws no map
  outputs.add(dir / "trajectory.tum");
  outputs.write(dir / "report.json", "new report");
  outputs.write(dir / "trajectory.tum", "0 0 0 0 0 0 0 1\n");
  outputs.commit();
  EXPECT_EQ(listing(dir), "notes.txt report.json trajectory.tum");
  EXPECT_EQ(read(dir / "report.json"), "new report");
  EXPECT_EQ(read(dir / "notes.txt"), "the user's own file");
}

TEST(OutputFiles, ARankThatDoesNotWriteChecksButNeverTouchesAFile) {
  const fs::path dir = fresh_dir("not-root");
  fs::create_directory(dir / "a-directory");
  put(dir / "report.json", "the root's report");
  put(dir / "map.png", "the root's map");
  io::OutputFiles outputs(false);
  EXPECT_FALSE(outputs.writes());
  EXPECT_THROW(outputs.add(dir / "a-directory"), io::UsageError);  // the same checks as the root
  outputs.add(dir / "report.json");
  outputs.add(dir / "map.png");  // declared, not written: the root's commit would remove it
  outputs.add(dir / "sub" / "new.txt");
  bool writer_ran = false;
  outputs.write(dir / "report.json", [&](std::ostream& out) {
    writer_ran = true;
    out << "this rank's report";
  });
  outputs.write(dir / "sub" / "new.txt", "new");
  EXPECT_THROW(outputs.write(dir / "undeclared.txt", "x"), std::logic_error);
  outputs.commit();
  EXPECT_FALSE(writer_ran);
  EXPECT_EQ(read(dir / "report.json"), "the root's report");
  EXPECT_EQ(read(dir / "map.png"), "the root's map");
  EXPECT_EQ(listing(dir), "a-directory map.png report.json");  // no staging, no sub/
}

TEST(OutputFiles, AFailedCommitRestoresWhatItReplaced) {
  const fs::path dir = fresh_dir("rollback");
  put(dir / "a.txt", "old a");
  put(dir / "other", "x");
  io::OutputFiles outputs;
  outputs.add(dir / "a.txt");
  outputs.add(dir / "b.txt");
  outputs.write(dir / "a.txt", "new a");
  outputs.write(dir / "b.txt", "new b");
  fs::create_symlink(dir / "other", dir / "b.txt");  // appears while the run works
  EXPECT_THROW(outputs.commit(), io::OutputError);
  EXPECT_EQ(read(dir / "a.txt"), "old a");
  EXPECT_TRUE(fs::is_symlink(dir / "b.txt"));
  EXPECT_EQ(read(dir / "other"), "x");
}

TEST(OutputFiles, RemovesWhatAKilledRunLeft) {
  const fs::path dir = fresh_dir("killed");
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);  // a process id that no longer runs
  const fs::path left = dir / (".antslam-staging." + std::to_string(child));
  fs::create_directory(left);
  put(left / "report.json", "half");
  const fs::path alive = dir / (".antslam-staging." + std::to_string(::getppid()));
  fs::create_directory(alive);  // a running process's staging directory stays
  io::OutputFiles outputs;
  outputs.add(dir / "x.txt");
  outputs.write(dir / "x.txt", "x");
  outputs.commit();
  EXPECT_FALSE(fs::exists(left));
  EXPECT_TRUE(fs::exists(alive));
  EXPECT_EQ(read(dir / "x.txt"), "x");
}

TEST(OutputFilesDeathTest, AnInterruptRemovesStagedFiles) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const fs::path dir = fresh_dir("interrupted");
  put(dir / "report.json", "old report");
  const auto interrupted_while_staging = [&] {
    io::handle_interrupts();
    io::OutputFiles outputs;
    outputs.add(dir / "report.json");
    outputs.write(dir / "report.json", "new report");
    ::kill(::getpid(), SIGINT);
    std::this_thread::sleep_for(std::chrono::seconds(10));  // the watcher ends the process first
    std::_Exit(0);
  };
  EXPECT_EXIT(interrupted_while_staging(), ::testing::KilledBySignal(SIGINT),
              "antslam: interrupted \\(Interrupt\\); temporary files removed");
  EXPECT_EQ(listing(dir), "report.json");
  EXPECT_EQ(read(dir / "report.json"), "old report");
}

}  // namespace
}  // namespace antslam::cli
