#include "antslam/frontend/image.hpp"

#include <png.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace antslam::frontend {

Image::Image(std::size_t width, std::size_t height, Rgb fill)
    : width_(width), height_(height), pixels_(width * height, fill) {
  if (width == 0 || height == 0) throw std::invalid_argument("image: empty size");
}

void Image::plot(long x, long y, Rgb colour) {
  if (x < 0 || y < 0 || static_cast<std::size_t>(x) >= width_ ||
      static_cast<std::size_t>(y) >= height_)
    return;
  at(static_cast<std::size_t>(x), static_cast<std::size_t>(y)) = colour;
}

namespace {

// libpng reports errors by longjmp to the setjmp in the calling function (no C++ exceptions
// through C frames); the message is kept for the exception thrown afterwards.
struct ErrorText {
  char text[200] = "";
};

[[noreturn]] void on_error(png_structp png, png_const_charp message) {
  auto* error = static_cast<ErrorText*>(png_get_error_ptr(png));
  std::snprintf(error->text, sizeof error->text, "%s", message);
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

void append(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), length);
}

struct Reader {
  const std::string* bytes;
  std::size_t offset;
};

void consume(png_structp png, png_bytep data, png_size_t length) {
  auto* in = static_cast<Reader*>(png_get_io_ptr(png));
  if (in->offset + length > in->bytes->size()) png_error(png, "truncated PNG data");
  std::memcpy(data, in->bytes->data() + in->offset, length);
  in->offset += length;
}

}  // namespace

std::string encode_png(const Image& image) {
  static_assert(sizeof(Rgb) == 3, "a row of Rgb pixels must be a PNG row");
  std::string out;
  ErrorText error;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, on_error, on_warning);
  if (png == nullptr) throw std::runtime_error("png: cannot create writer");
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error(std::string("png: ") + error.text);
  }
  png_set_write_fn(png, &out, append, nullptr);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width()),
               static_cast<png_uint_32>(image.height()), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (std::size_t y = 0; y < image.height(); ++y)
    png_write_row(png, reinterpret_cast<png_const_bytep>(&image.at(0, y)));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

Image decode_png(const std::string& bytes) {
  if (bytes.size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) != 0)
    throw std::runtime_error("not a PNG file");
  ErrorText error;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, on_error, on_warning);
  if (png == nullptr) throw std::runtime_error("png: cannot create reader");
  png_infop info = png_create_info_struct(png);
  Reader reader{&bytes, 0};
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw std::runtime_error(std::string("png: ") + error.text);
  }
  png_set_read_fn(png, &reader, consume);
  png_read_info(png, info);
  const png_uint_32 width = png_get_image_width(png, info);
  const png_uint_32 height = png_get_image_height(png, info);
  if (png_get_color_type(png, info) != PNG_COLOR_TYPE_RGB || png_get_bit_depth(png, info) != 8 ||
      width == 0 || height == 0 || width > 100000 || height > 100000)
    png_error(png, "not an 8-bit RGB image of a sane size");
  std::vector<Rgb> pixels(static_cast<std::size_t>(width) * height);
  // Re-arm the jump after `pixels` exists, so that an error below does not skip its destructor.
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw std::runtime_error(std::string("png: ") + error.text);
  }
  for (png_uint_32 y = 0; y < height; ++y)
    png_read_row(png,
                 reinterpret_cast<png_bytep>(pixels.data() + static_cast<std::size_t>(y) * width),
                 nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  Image image(width, height);
  for (std::size_t y = 0; y < height; ++y)
    for (std::size_t x = 0; x < width; ++x) image.at(x, y) = pixels[y * width + x];
  return image;
}

}  // namespace antslam::frontend
