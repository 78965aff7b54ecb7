#include "antslam/io/output_files.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <set>
#include <string>

#include "antslam/dist/command_world.hpp"
#include "antslam/io/errors.hpp"
#include "antslam/io/interrupts.hpp"

namespace antslam::io {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kStagingPrefix = ".antslam-staging.";

/// Why no directory can be made in `dir` (where the outputs' staging directory or missing
/// parents will go), or empty if one can: tried with a probe made and removed at once, since
/// access(2) says yes to root where the file system says no (/proc, a read-only mount).
std::string cannot_make_directory_in(const fs::path& dir) {
  const fs::path probe = dir / (".antslam-probe." + std::to_string(::getpid()));
  if (::mkdir(probe.c_str(), 0700) != 0) {
    if (errno == EEXIST) return {};
    return "cannot create a directory in " + dir.string() + ": " + std::strerror(errno);
  }
  ::rmdir(probe.c_str());
  return {};
}

/// Why `path` cannot be an output file, or empty if it can.
std::string output_problem(const fs::path& path) {
  if (path.empty()) return "the output path is empty";
  if (!path.has_filename()) return "names a directory, expected a file";
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(path, ec);
  if (fs::exists(status)) {
    if (fs::is_symlink(status)) return "is a symbolic link (outputs replace only regular files)";
    if (fs::is_directory(status)) return "is a directory, expected a file";
    if (!fs::is_regular_file(status))
      return "is not a regular file (a FIFO, socket or device; outputs replace only regular "
             "files)";
  }
  // The nearest existing ancestor must be a directory we may write into (links followed).
  fs::path dir = path.parent_path();
  for (;;) {
    if (dir.empty()) dir = ".";
    const fs::file_status s = fs::status(dir, ec);
    if (fs::exists(s)) {
      if (!fs::is_directory(s)) return dir.string() + " is not a directory";
      if (::access(dir.c_str(), W_OK | X_OK) != 0) return dir.string() + " is not writable";
      return cannot_make_directory_in(dir);
    }
    if (dir == ".") return {};
    dir = dir.parent_path();
  }
}

/// Whether a process with this id runs (a staging directory of a dead one is stale).
bool process_alive(long pid) { return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH; }

/// Removes the staging directories that killed antslam processes left in `dir`.
void remove_stale_staging(const fs::path& dir) {
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(kStagingPrefix)) continue;
    long pid = 0;
    const char* first = name.data() + kStagingPrefix.size();
    const char* last = name.data() + name.size();
    const auto [end, error] = std::from_chars(first, last, pid);
    if (error != std::errc() || end != last || pid <= 0 || pid == ::getpid()) continue;
    if (!process_alive(pid)) {
      std::error_code ignored;
      fs::remove_all(entry.path(), ignored);
    }
  }
}

void sync_to_disk(const fs::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

[[noreturn]] void fail(const fs::path& path, const std::string& problem) {
  throw OutputError(path.string() + ": " + problem);
}

}  // namespace

OutputFiles::OutputFiles() : writes_(dist::command_world().is_root()) {}

OutputFiles::~OutputFiles() {
  if (!committed_) discard();
}

fs::path OutputFiles::add(const fs::path& path) {
  const std::string problem = output_problem(path);
  if (!problem.empty()) throw UsageError(path.string() + ": " + problem);
  const auto resolved = [](const fs::path& p) {
    std::error_code ec;
    const fs::path r = fs::weakly_canonical(p, ec);
    return ec ? p.lexically_normal() : r;
  };
  for (const Target& t : targets_)
    if (resolved(t.path) == resolved(path))
      throw UsageError(path.string() + ": named twice as an output");
  targets_.push_back({path, {}});
  return path;
}

OutputFiles::Target& OutputFiles::find(const fs::path& path) {
  for (Target& t : targets_)
    if (t.path == path) return t;
  throw std::logic_error(path.string() + ": written but not declared as an output");
}

const fs::path& OutputFiles::staging_for(const fs::path& target) {
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const auto found = staging_.find(parent);
  if (found != staging_.end()) return found->second;
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) fail(target, "cannot create the directory " + parent.string() + ": " + ec.message());
  remove_stale_staging(parent);
  const fs::path staging = parent / (std::string(kStagingPrefix) + std::to_string(::getpid()));
  create_temporary(staging, [&] {
    fs::create_directory(staging, ec);
    if (ec) fail(target, "cannot create " + staging.string() + ": " + ec.message());
  });
  return staging_.emplace(parent, staging).first->second;
}

void OutputFiles::write(const fs::path& path, const std::function<void(std::ostream&)>& writer) {
  Target& target = find(path);
  if (!writes_) return;
  const fs::path staged = staging_for(path) / path.filename();
  {
    std::ofstream out(staged, std::ios::binary | std::ios::trunc);
    if (!out) fail(path, "cannot open " + staged.string() + " for writing");
    writer(out);
    out.flush();
    if (!out) fail(path, "write failed (disk full?)");
  }
  sync_to_disk(staged, O_RDONLY);
  target.staged = staged;
}

void OutputFiles::write(const fs::path& path, std::string_view bytes) {
  write(path, [&](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
}

void OutputFiles::commit() {
  if (!writes_) {
    committed_ = true;
    return;
  }
  without_interrupts([&] {
    // (target, its old content moved aside, or empty if there was none)
    std::vector<std::pair<fs::path, fs::path>> replaced;
    try {
      for (const Target& t : targets_) {
        if (t.staged.empty()) continue;
        const std::string problem = output_problem(t.path);
        if (!problem.empty()) fail(t.path, problem);
        fs::path old;
        if (fs::exists(fs::symlink_status(t.path))) {
          old = t.staged;
          old += ".old";
          fs::rename(t.path, old);
        }
        replaced.emplace_back(t.path, old);
        fs::rename(t.staged, t.path);
      }
    } catch (const std::exception& e) {
      for (auto it = replaced.rbegin(); it != replaced.rend(); ++it) {
        std::error_code ignored;
        if (it->second.empty())
          fs::remove(it->first, ignored);
        else
          fs::rename(it->second, it->first, ignored);
      }
      if (dynamic_cast<const OutputError*>(&e) != nullptr) throw;
      const auto* fs_error = dynamic_cast<const fs::filesystem_error*>(&e);
      fail(replaced.empty() ? targets_.front().path : replaced.back().first,
           "cannot move into place: " + (fs_error ? fs_error->code().message() : e.what()));
    }
    std::set<fs::path> directories;
    for (const Target& t : targets_) {
      std::error_code ignored;
      if (t.staged.empty() && fs::is_regular_file(fs::symlink_status(t.path)))
        fs::remove(t.path, ignored);
      directories.insert(t.path.has_parent_path() ? t.path.parent_path() : fs::path("."));
    }
    for (const fs::path& dir : directories) sync_to_disk(dir, O_RDONLY | O_DIRECTORY);
    discard();
    committed_ = true;
  });
}

void OutputFiles::discard() noexcept {
  for (const auto& [parent, staging] : staging_) remove_temporary(staging);
  staging_.clear();
  for (Target& t : targets_) t.staged.clear();
}

}  // namespace antslam::io
