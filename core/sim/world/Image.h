// Image: an 8-bit raster with 1 (gray) or 3 (RGB) interleaved channels, row 0 at the top as in
// image files. The common currency of the PNG/PGM readers and writers of the simulator's worlds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/common/Errors.h"

namespace rgnav {

template <int Channels>
struct Image {
  static_assert(Channels == 1 || Channels == 3, "gray or RGB");
  static constexpr int kChannels = Channels;

  Image() = default;
  // Throws InvalidArgumentError for a non-positive size.
  Image(int width, int height, std::uint8_t fill = 0) : width_(width), height_(height) {
    if (width <= 0 || height <= 0) throw InvalidArgumentError("Image: size must be positive");
    pixels_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * Channels, fill);
  }

  int width() const { return width_; }
  int height() const { return height_; }
  // Channel `channel` of the pixel at (col, row); row 0 is the top row.
  std::uint8_t at(int col, int row, int channel = 0) const { return pixels_[offset(col, row) + channel]; }
  void set(int col, int row, std::uint8_t value, int channel = 0) { pixels_[offset(col, row) + channel] = value; }
  // Row-major, channels interleaved.
  const std::vector<std::uint8_t>& pixels() const { return pixels_; }
  std::vector<std::uint8_t>& pixels() { return pixels_; }

  friend bool operator==(const Image&, const Image&) = default;

 private:
  std::size_t offset(int col, int row) const {
    return (static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(col)) * Channels;
  }

  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> pixels_;
};

using GrayImage = Image<1>;
using RgbImage = Image<3>;

}  // namespace rgnav
