#pragma once
// The files one command writes, as one transaction:
//   1. declared before any work, and checked then (add): a directory, a symbolic link, a FIFO
//      or another non-regular file at the path, a parent that is a file, or a directory that
//      cannot be written is refused at once (UsageError), not after an hour of solving;
//   2. written into a staging directory ".antslam-staging.<pid>" beside each target (write);
//   3. moved into place together (commit): with interrupts held back, every written file
//      replaces its target by rename(2), and the declared files this run did not write (the
//      outputs of an earlier run, e.g. maps before --no-maps) are removed, so that a directory
//      never mixes the outputs of two runs. If a rename fails, the targets already replaced get
//      their old content back.
// Until commit, the targets are untouched; an exception, an interrupt (interrupts.hpp) or the
// destructor removes the staging directories. A staging directory left by a killed process is
// removed by the next run that writes beside it.
// A run over several processes writes on its root only: the other ranks declare the same files
// (and so refuse the same bad paths) but never stage, write, replace or remove anything.

#include <filesystem>
#include <functional>
#include <map>
#include <ostream>
#include <string_view>
#include <vector>

namespace antslam::io {

class OutputFiles {
 public:
  /// Writes if this process is the root of the command's processes (dist/command_world.hpp).
  OutputFiles();
  /// Writes only if `this_process_writes`; otherwise add() checks and the rest does nothing.
  explicit OutputFiles(bool this_process_writes) : writes_(this_process_writes) {}
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  /// Declares an output file and checks that it can be written; throws UsageError naming the
  /// path and the problem. Returns the path.
  std::filesystem::path add(const std::filesystem::path& path);

  /// Whether this process writes (and so runs the writers of write()).
  bool writes() const { return writes_; }

  /// Writes the content of a declared file into its staging directory (creating the target's
  /// parent directories). Throws OutputError naming the file if anything fails.
  void write(const std::filesystem::path& path, const std::function<void(std::ostream&)>& writer);
  void write(const std::filesystem::path& path, std::string_view bytes);

  /// Moves every written file into place and removes the declared files that were not written
  /// (see above). Throws OutputError naming the file if anything fails.
  void commit();

 private:
  struct Target {
    std::filesystem::path path;    ///< where the file goes
    std::filesystem::path staged;  ///< its content, once written; empty before
  };
  /// The staging directory beside `target` (made on first use).
  const std::filesystem::path& staging_for(const std::filesystem::path& target);
  Target& find(const std::filesystem::path& path);
  void discard() noexcept;

  std::vector<Target> targets_;
  std::map<std::filesystem::path, std::filesystem::path> staging_;  ///< parent -> staging dir
  bool writes_ = true;
  bool committed_ = false;
};

}  // namespace antslam::io
