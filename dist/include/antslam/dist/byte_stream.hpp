#pragma once
// Values to bytes and back, for what ranks send each other: trivially copyable values as their
// bytes (all ranks of a run share one architecture, as MPI_BYTE assumes), strings and vectors
// with their length first. A reader that runs out of bytes throws instead of reading past them.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace antslam::dist {

class ByteWriter {
 public:
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void value(const T& v) {
    const auto* first = reinterpret_cast<const std::byte*>(&v);
    bytes_.insert(bytes_.end(), first, first + sizeof(T));
  }
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void values(std::span<const T> vs) {
    value(static_cast<std::uint64_t>(vs.size()));
    const auto* first = reinterpret_cast<const std::byte*>(vs.data());
    bytes_.insert(bytes_.end(), first, first + vs.size_bytes());
  }
  void text(std::string_view s) { values(std::span<const char>(s.data(), s.size())); }
  /// A presence byte, then the value if there is one: the bytes of a std::optional itself
  /// include padding and, when empty, an unset value, so equal optionals could differ.
  template <class T>
  void optional(const std::optional<T>& v) {
    optional(v, [](ByteWriter& out, const T& x) { out.value(x); });
  }
  /// The same, with `write(*this, value)` for a value that is not sent as its bytes.
  template <class T, class Write>
  void optional(const std::optional<T>& v, Write write) {
    value(static_cast<std::uint8_t>(v.has_value()));
    if (v) write(*this, *v);
  }

  const std::vector<std::byte>& bytes() const { return bytes_; }
  std::vector<std::byte> take() { return std::move(bytes_); }

 private:
  std::vector<std::byte> bytes_;
};

class ByteReader {
 public:
  explicit ByteReader(std::span<const std::byte> bytes) : bytes_(bytes) {}

  template <class T>
  requires std::is_trivially_copyable_v<T> T value() {
    T v;
    std::memcpy(&v, take(sizeof(T)).data(), sizeof(T));
    return v;
  }
  template <class T>
  requires std::is_trivially_copyable_v<T> std::vector<T> values() {
    const auto count = value<std::uint64_t>();
    if (count > remaining() / (sizeof(T) == 0 ? 1 : sizeof(T)))
      throw std::runtime_error("received message ends inside a list");
    std::vector<T> vs(static_cast<std::size_t>(count));
    if (!vs.empty())
      std::memcpy(vs.data(), take(vs.size() * sizeof(T)).data(), vs.size() * sizeof(T));
    return vs;
  }
  std::string text() {
    const auto chars = values<char>();
    return {chars.begin(), chars.end()};
  }
  template <class T>
  std::optional<T> optional() {
    if (value<std::uint8_t>() == 0) return std::nullopt;
    return value<T>();
  }

  std::size_t remaining() const { return bytes_.size() - position_; }

 private:
  std::span<const std::byte> take(std::size_t n) {
    if (n > remaining()) throw std::runtime_error("received message is shorter than its content");
    const auto part = bytes_.subspan(position_, n);
    position_ += n;
    return part;
  }

  std::span<const std::byte> bytes_;
  std::size_t position_ = 0;
};

}  // namespace antslam::dist
