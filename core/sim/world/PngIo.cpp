// PNG reading and writing with libpng's low-level API; libpng errors come back through setjmp
// as a FormatError or FileError naming the path, libpng warnings are ignored.
#include "core/sim/world/PngIo.h"

#include <png.h>

#include <csetjmp>
#include <cstring>
#include <vector>

#include "core/common/AtomicFile.h"
#include "core/common/Errors.h"

namespace rgnav {
namespace {

// OpenCV's RGB-to-gray weights in libpng's 1/100000 fixed point (blue gets the rest, 0.114).
constexpr png_fixed_point kRedWeight = 29900;
constexpr png_fixed_point kGreenWeight = 58700;
// Largest image accepted: 2^28 pixels (a 16384 x 16384 map), so a damaged header cannot ask
// for terabytes.
constexpr std::uint64_t kMaxPixels = std::uint64_t{1} << 28;

struct PngErrorText {
  std::string message;
};

[[noreturn]] void onPngError(png_structp png, png_const_charp message) {
  static_cast<PngErrorText*>(png_get_error_ptr(png))->message = message;
  png_longjmp(png, 1);
}

void onPngWarning(png_structp, png_const_charp) {}

// Runs libpng calls; false if libpng reported an error. `body` must hold no object with a
// destructor, because a libpng error leaves it by longjmp.
template <typename Body>
bool guarded(png_structp png, Body&& body) {
  if (setjmp(png_jmpbuf(png))) return false;
  body();
  return true;
}

struct ReadCursor {
  const std::string* bytes;
  std::size_t position;
};

void readFromMemory(png_structp png, png_bytep out, png_size_t count) {
  auto* cursor = static_cast<ReadCursor*>(png_get_io_ptr(png));
  if (count > cursor->bytes->size() - cursor->position) png_error(png, "file is truncated");
  std::memcpy(out, cursor->bytes->data() + cursor->position, count);
  cursor->position += count;
}

void writeToMemory(png_structp png, png_bytep data, png_size_t count) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), count);
}

void flushMemory(png_structp) {}

class ReadStruct {
 public:
  explicit ReadStruct(PngErrorText& errors)
      : png_(png_create_read_struct(PNG_LIBPNG_VER_STRING, &errors, onPngError, onPngWarning)),
        info_(png_ != nullptr ? png_create_info_struct(png_) : nullptr) {
    if (info_ == nullptr) throw std::bad_alloc();
  }
  ~ReadStruct() { png_destroy_read_struct(&png_, &info_, nullptr); }
  ReadStruct(const ReadStruct&) = delete;
  ReadStruct& operator=(const ReadStruct&) = delete;
  png_structp png() const { return png_; }
  png_infop info() const { return info_; }

 private:
  png_structp png_;
  png_infop info_;
};

class WriteStruct {
 public:
  explicit WriteStruct(PngErrorText& errors)
      : png_(png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, onPngError, onPngWarning)),
        info_(png_ != nullptr ? png_create_info_struct(png_) : nullptr) {
    if (info_ == nullptr) throw std::bad_alloc();
  }
  ~WriteStruct() { png_destroy_write_struct(&png_, &info_); }
  WriteStruct(const WriteStruct&) = delete;
  WriteStruct& operator=(const WriteStruct&) = delete;
  png_structp png() const { return png_; }
  png_infop info() const { return info_; }

 private:
  png_structp png_;
  png_infop info_;
};

// Asks libpng for 8-bit single-channel rows whatever the stored format.
void requestGray8(png_structp png, png_infop info) {
  const png_byte colorType = png_get_color_type(png, info);
  if (png_get_bit_depth(png, info) == 16) png_set_strip_16(png);
  if (colorType == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (colorType == PNG_COLOR_TYPE_GRAY) png_set_expand_gray_1_2_4_to_8(png);
  if (colorType & PNG_COLOR_MASK_ALPHA) png_set_strip_alpha(png);
  if (colorType & PNG_COLOR_MASK_COLOR) {
    png_set_rgb_to_gray_fixed(png, PNG_ERROR_ACTION_NONE, kRedWeight, kGreenWeight);
  }
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  if (png_get_channels(png, info) != 1 || png_get_bit_depth(png, info) != 8) {
    png_error(png, "cannot convert this PNG format to 8-bit gray");
  }
}

// Row pointers into an image's pixels; libpng's row type is not const, but writing never
// changes the rows (no write transforms are set).
template <int Channels>
std::vector<png_bytep> rowPointers(const Image<Channels>& image) {
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height()));
  const std::size_t stride = static_cast<std::size_t>(image.width()) * Channels;
  auto* base = const_cast<png_bytep>(image.pixels().data());
  for (std::size_t r = 0; r < rows.size(); ++r) rows[r] = base + r * stride;
  return rows;
}

template <int Channels>
void writePngImage(const std::string& path, const Image<Channels>& image) {
  if (image.width() <= 0) throw InvalidArgumentError(path + ": cannot write an empty image");
  PngErrorText errors;
  WriteStruct png(errors);
  std::string encoded;
  const std::vector<png_bytep> rows = rowPointers(image);
  const bool ok = guarded(png.png(), [&] {
    png_set_write_fn(png.png(), &encoded, writeToMemory, flushMemory);
    png_set_IHDR(png.png(), png.info(), static_cast<png_uint_32>(image.width()),
                 static_cast<png_uint_32>(image.height()), 8,
                 Channels == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png.png(), png.info());
    png_write_image(png.png(), const_cast<png_bytepp>(rows.data()));
    png_write_end(png.png(), nullptr);
  });
  if (!ok) throw FileError(path + ": cannot encode PNG: " + errors.message);
  writeFileAtomically(path, encoded);
}

}  // namespace

bool isPng(const std::string& bytes) {
  return bytes.size() >= 8 && png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) == 0;
}

GrayImage decodePngGray(const std::string& bytes, const std::string& path) {
  if (!isPng(bytes)) throw FormatError(path, 0, "not a PNG file (no PNG signature)");
  PngErrorText errors;
  ReadStruct png(errors);
  ReadCursor cursor{&bytes, 0};
  const bool headerOk = guarded(png.png(), [&] {
    png_set_read_fn(png.png(), &cursor, readFromMemory);
    png_read_info(png.png(), png.info());
    requestGray8(png.png(), png.info());
  });
  if (!headerOk) throw FormatError(path, 0, "damaged PNG header: " + errors.message);
  const png_uint_32 width = png_get_image_width(png.png(), png.info());
  const png_uint_32 height = png_get_image_height(png.png(), png.info());
  if (std::uint64_t{width} * height > kMaxPixels) {
    throw FormatError(path, 0, "PNG too large: " + std::to_string(width) + "x" + std::to_string(height));
  }
  GrayImage image(static_cast<int>(width), static_cast<int>(height));
  const std::vector<png_bytep> rows = rowPointers(image);
  const bool pixelsOk = guarded(png.png(), [&] {
    png_read_image(png.png(), const_cast<png_bytepp>(rows.data()));
    png_read_end(png.png(), nullptr);
  });
  if (!pixelsOk) throw FormatError(path, 0, "damaged PNG data: " + errors.message);
  return image;
}

void writePng(const std::string& path, const GrayImage& image) { writePngImage(path, image); }
void writePng(const std::string& path, const RgbImage& image) { writePngImage(path, image); }

}  // namespace rgnav
