#include "antslam/io/atomic_file.hpp"

#include "antslam/io/output_files.hpp"

namespace antslam::io {

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& writer) {
  OutputFiles outputs;
  outputs.add(path);
  outputs.write(path, writer);
  outputs.commit();
}

void write_atomically(const std::filesystem::path& path, std::string_view bytes) {
  OutputFiles outputs;
  outputs.add(path);
  outputs.write(path, bytes);
  outputs.commit();
}

}  // namespace antslam::io
