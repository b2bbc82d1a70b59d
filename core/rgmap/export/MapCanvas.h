// MapCanvas: an RGB raster over a rectangle of the map frame, with the few drawing operations the
// RG Map's PNG export needs (RgMapPng.h): pixels, thick straight lines (Bresenham, "Algorithm for
// computer control of a digital plotter", 1965, with a square brush), filled discs and small
// numbers in a 3 x 5 pixel digit font. Pixel (col, row) covers [min.x + col * res, ...) x
// (max.y - (row + 1) * res, max.y - row * res]: row 0 is the top, as in image files, so the map's
// y axis points up in the picture. Drawing outside the raster is clipped.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>

#include "core/rgmap/export/MapColours.h"
#include "core/sim/world/Image.h"

namespace rgnav {

class MapCanvas {
 public:
  // At most 8000 x 8000 pixels (192 MB): a 400 m building at 5 cm per pixel.
  static constexpr int kMaxSidePixels = 8000;

  // A canvas of ceil(extent size / resolutionM) pixels filled with `background`. Throws
  // InvalidArgumentError for an empty extent, a non-positive resolution or more than
  // kMaxSidePixels pixels per side.
  MapCanvas(const Eigen::AlignedBox2d& extent, double resolutionM, const Rgb& background);

  const RgbImage& image() const { return image_; }
  double resolutionM() const { return resolutionM_; }
  // The map-frame position of the raster's bottom-left corner.
  Eigen::Vector2d originM() const { return origin_; }

  // The pixel containing `p` (may lie outside the raster).
  Eigen::Vector2i pixelOf(const Eigen::Vector2d& p) const;

  void setPixel(int col, int row, const Rgb& colour);
  void line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Rgb& colour, int widthPixels);
  void disc(const Eigen::Vector2d& centre, int radiusPixels, const Rgb& colour);
  // `number` in digits `scale` pixels per font pixel, its bottom centre `liftPixels` above `at`.
  void number(const Eigen::Vector2d& at, std::uint64_t number, int scale, int liftPixels, const Rgb& colour);

 private:
  void stamp(int col, int row, int widthPixels, const Rgb& colour);

  double resolutionM_;
  Eigen::Vector2d origin_;
  RgbImage image_;
};

}  // namespace rgnav
