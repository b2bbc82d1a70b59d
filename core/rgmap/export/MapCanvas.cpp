// A colour raster over the map frame on OpenCV's drawing functions; see MapCanvas.h.
#include "core/rgmap/export/MapCanvas.h"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

// Digits 0-9, 5 rows of 3 pixels each, top row first, the left pixel in bit 2.
constexpr std::uint8_t kDigits[10][5] = {
    {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1},
    {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7}};
constexpr int kDigitWidth = 3, kDigitHeight = 5, kDigitGap = 1;

int pixels(double metres, double resolutionM) {
  const double n = std::ceil(metres / resolutionM);
  if (!(n >= 1.0) || n > MapCanvas::kMaxSidePixels)
    throw InvalidArgumentError("map canvas: the picture would be empty or wider than " +
                               std::to_string(MapCanvas::kMaxSidePixels) + " pixels");
  return int(n);
}

cv::Scalar bgr(const Rgb& c) { return {double(c.b), double(c.g), double(c.r)}; }

}  // namespace

MapCanvas::MapCanvas(const Eigen::AlignedBox2d& extent, double resolutionM, const Rgb& background)
    : resolutionM_(resolutionM), origin_(extent.min()) {
  if (extent.isEmpty() || !std::isfinite(resolutionM) || !(resolutionM > 0.0) || !extent.sizes().allFinite())
    throw InvalidArgumentError("map canvas: need a finite, non-empty extent and a positive resolution");
  image_ = cv::Mat(pixels(extent.sizes().y(), resolutionM), pixels(extent.sizes().x(), resolutionM), CV_8UC3,
                   bgr(background));
}

Eigen::Vector2i MapCanvas::pixelOf(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d cell = ((p - origin_) / resolutionM_).array().floor();
  return {int(cell.x()), image_.rows - 1 - int(cell.y())};
}

cv::Point MapCanvas::boundedPixelOf(const Eigen::Vector2d& p) const {
  constexpr double kLimit = 4.0 * kMaxSidePixels;
  const Eigen::Array2d cell = ((p - origin_) / resolutionM_).array().floor().cwiseMax(-kLimit).cwiseMin(kLimit);
  return {int(cell.x()), image_.rows - 1 - int(cell.y())};
}

Rgb MapCanvas::colourAt(int col, int row) const {
  const cv::Vec3b p = image_.at<cv::Vec3b>(row, col);
  return {p[2], p[1], p[0]};
}

void MapCanvas::setPixel(int col, int row, const Rgb& colour) {
  if (col < 0 || row < 0 || col >= image_.cols || row >= image_.rows) return;
  image_.at<cv::Vec3b>(row, col) = {colour.b, colour.g, colour.r};
}

void MapCanvas::fill(const cv::Mat& mask, const Rgb& colour) {
  if (mask.size() != image_.size() || mask.type() != CV_8UC1)
    throw InvalidArgumentError("map canvas: a mask must be 8-bit gray and of the canvas's size");
  image_.setTo(bgr(colour), mask);
}

void MapCanvas::line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Rgb& colour, int widthPixels) {
  const cv::Point from = boundedPixelOf(a), to = boundedPixelOf(b);
  // The square brush: the 1-pixel line shifted to every pixel of a widthPixels square.
  const int lo = -(widthPixels - 1) / 2, hi = widthPixels / 2;
  for (int dy = lo; dy <= hi; ++dy)
    for (int dx = lo; dx <= hi; ++dx)
      cv::line(image_, from + cv::Point(dx, dy), to + cv::Point(dx, dy), bgr(colour), 1, cv::LINE_8);
}

void MapCanvas::disc(const Eigen::Vector2d& centre, int radiusPixels, const Rgb& colour) {
  cv::circle(image_, boundedPixelOf(centre), radiusPixels, bgr(colour), cv::FILLED, cv::LINE_8);
}

void MapCanvas::number(const Eigen::Vector2d& at, std::uint64_t number, int scale, int liftPixels,
                       const Rgb& colour) {
  const std::string digits = std::to_string(number);
  const int width = scale * (int(digits.size()) * (kDigitWidth + kDigitGap) - kDigitGap);
  const cv::Point base = boundedPixelOf(at);
  const int left = base.x - width / 2, top = base.y - liftPixels - scale * kDigitHeight;
  for (std::size_t k = 0; k < digits.size(); ++k) {
    const int x0 = left + int(k) * scale * (kDigitWidth + kDigitGap);
    for (int r = 0; r < kDigitHeight; ++r)
      for (int c = 0; c < kDigitWidth; ++c)
        if (kDigits[digits[k] - '0'][r] >> (kDigitWidth - 1 - c) & 1)
          cv::rectangle(image_, cv::Rect(x0 + c * scale, top + r * scale, scale, scale), bgr(colour), cv::FILLED);
  }
}

}  // namespace rgnav
