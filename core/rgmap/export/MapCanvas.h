// MapCanvas: a colour raster (cv::Mat, 8-bit BGR, OpenCV's channel order) over a rectangle of the
// map frame, with the few drawing operations the RG Map's PNG export needs (RgMapPng.h): masks
// and single pixels painted in a colour, lines (cv::line, 8-connected, no anti-aliasing), filled
// discs (cv::circle) and small numbers. Pixel (col, row) covers [min.x + col * res, ...) x
// (max.y - (row + 1) * res, max.y - row * res]: row 0 is the top, as in image files, so the map's
// y axis points up in the picture. Drawing outside the raster is clipped.
// Our own code where OpenCV draws differently from what the picture needs: a line wider than one
// pixel is the 1-pixel cv::line repeated at every offset of a square brush (cv::line's own thick
// lines are filled polygons with round caps, about one pixel wider, which blur the 2- and 3-pixel
// outlines of hallway areas and doors), and numbers use a 3 x 5 pixel digit font (OpenCV's Hershey
// fonts are stroked vector fonts, not legible at the 10-pixel height of region labels).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <opencv2/core.hpp>

#include "core/rgmap/export/MapColours.h"

namespace rgnav {

class MapCanvas {
 public:
  // At most 8000 x 8000 pixels (192 MB): a 400 m building at 5 cm per pixel.
  static constexpr int kMaxSidePixels = 8000;

  // A canvas of ceil(extent size / resolutionM) pixels filled with `background`. Throws
  // InvalidArgumentError for an empty extent, a non-positive resolution or more than
  // kMaxSidePixels pixels per side.
  MapCanvas(const Eigen::AlignedBox2d& extent, double resolutionM, const Rgb& background);

  // CV_8UC3, BGR.
  const cv::Mat& image() const { return image_; }
  double resolutionM() const { return resolutionM_; }
  // The map-frame position of the raster's bottom-left corner.
  Eigen::Vector2d originM() const { return origin_; }

  // The pixel containing `p` (may lie outside the raster).
  Eigen::Vector2i pixelOf(const Eigen::Vector2d& p) const;
  // The colour of pixel (col, row), which must lie inside the raster.
  Rgb colourAt(int col, int row) const;

  // Paints one pixel; nothing if it lies outside the raster.
  void setPixel(int col, int row, const Rgb& colour);
  // Paints every pixel where `mask` (CV_8UC1, the raster's size) is non-zero.
  void fill(const cv::Mat& mask, const Rgb& colour);
  void line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Rgb& colour, int widthPixels);
  void disc(const Eigen::Vector2d& centre, int radiusPixels, const Rgb& colour);
  // `number` in digits `scale` pixels per font pixel, its bottom centre `liftPixels` above `at`.
  void number(const Eigen::Vector2d& at, std::uint64_t number, int scale, int liftPixels, const Rgb& colour);

 private:
  // pixelOf, kept within 4 kMaxSidePixels of the raster so that far-off points stay ints.
  cv::Point boundedPixelOf(const Eigen::Vector2d& p) const;

  double resolutionM_;
  Eigen::Vector2d origin_;
  cv::Mat image_;
};

}  // namespace rgnav
