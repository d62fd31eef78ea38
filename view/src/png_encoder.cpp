// PNG encoding through libpng: 8-bit RGB, maximum compression, no time or
// text chunks, so equal images give equal bytes.
#include <png.h>

#include <vector>

#include "rdmesh/errors.h"
#include "rdmesh/picture.h"

namespace rdmesh::view {
namespace {

struct Sink {
  std::vector<std::uint8_t>* out;
  bool failed = false;
};

void write_bytes(png_structp png, png_bytep data, png_size_t size) {
  auto* sink = static_cast<Sink*>(png_get_io_ptr(png));
  if (sink->failed) return;
  try {
    sink->out->insert(sink->out->end(), data, data + size);
  } catch (...) {  // never let an exception cross libpng's C frames
    sink->failed = true;
  }
}

void flush_bytes(png_structp) {}

/// libpng reports errors by longjmp; nothing is printed.
void on_error(png_structp png, png_const_charp) { png_longjmp(png, 1); }
void on_warning(png_structp, png_const_charp) {}

/// False when libpng failed. Only plain data lives across setjmp here.
bool encode(const Image& image, Sink& sink) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, on_error, on_warning);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, &sink, write_bytes, flush_bytes);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, 6);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) {
    png_write_row(png, image.rgb.data() + 3 * static_cast<std::size_t>(y) * image.width);
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != 3 * static_cast<std::size_t>(image.width) * image.height) {
    throw InternalError("encode_png: the image's size and pixel data disagree");
  }
  std::vector<std::uint8_t> bytes;
  Sink sink{&bytes};
  if (!encode(image, sink) || sink.failed)
    throw InternalError("encode_png: libpng failed to encode the image");
  return bytes;
}

}  // namespace rdmesh::view
