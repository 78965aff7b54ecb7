#pragma once
// RGB images and their PNG encoding (libpng, in memory: write the bytes with
// io::write_atomically).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace antslam::frontend {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;  ///< 0-255 intensities of red, green and blue
  bool operator==(const Rgb&) const = default;
};

class Image {
 public:
  Image(std::size_t width, std::size_t height, Rgb fill = {});
  std::size_t width() const { return width_; }
  std::size_t height() const { return height_; }
  Rgb& at(std::size_t x, std::size_t y) { return pixels_[y * width_ + x]; }
  const Rgb& at(std::size_t x, std::size_t y) const { return pixels_[y * width_ + x]; }
  /// Sets the pixel if it lies inside the image.
  void plot(long x, long y, Rgb colour);

 private:
  std::size_t width_, height_;
  std::vector<Rgb> pixels_;
};

/// The image as a PNG file (8-bit RGB), in memory. Throws std::runtime_error if libpng fails.
std::string encode_png(const Image& image);

/// Decodes an 8-bit RGB PNG made by encode_png (for tests and tools). Throws
/// std::runtime_error naming the problem on anything else.
Image decode_png(const std::string& bytes);

}  // namespace antslam::frontend
