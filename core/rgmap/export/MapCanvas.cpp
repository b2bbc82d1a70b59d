// An RGB raster over the map frame; see MapCanvas.h.
#include "core/rgmap/export/MapCanvas.h"

#include <cmath>
#include <cstdlib>
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

}  // namespace

MapCanvas::MapCanvas(const Eigen::AlignedBox2d& extent, double resolutionM, const Rgb& background)
    : resolutionM_(resolutionM), origin_(extent.min()) {
  if (extent.isEmpty() || !std::isfinite(resolutionM) || !(resolutionM > 0.0) || !extent.sizes().allFinite())
    throw InvalidArgumentError("map canvas: need a finite, non-empty extent and a positive resolution");
  image_ = RgbImage(pixels(extent.sizes().x(), resolutionM), pixels(extent.sizes().y(), resolutionM));
  for (int row = 0; row < image_.height(); ++row)
    for (int col = 0; col < image_.width(); ++col) setPixel(col, row, background);
}

Eigen::Vector2i MapCanvas::pixelOf(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d cell = ((p - origin_) / resolutionM_).array().floor();
  return {int(cell.x()), image_.height() - 1 - int(cell.y())};
}

void MapCanvas::setPixel(int col, int row, const Rgb& colour) {
  if (col < 0 || row < 0 || col >= image_.width() || row >= image_.height()) return;
  image_.set(col, row, colour.r, 0);
  image_.set(col, row, colour.g, 1);
  image_.set(col, row, colour.b, 2);
}

void MapCanvas::stamp(int col, int row, int widthPixels, const Rgb& colour) {
  const int lo = -(widthPixels - 1) / 2, hi = widthPixels / 2;
  for (int dr = lo; dr <= hi; ++dr)
    for (int dc = lo; dc <= hi; ++dc) setPixel(col + dc, row + dr, colour);
}

void MapCanvas::line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Rgb& colour, int widthPixels) {
  // Bounded so that a far-off end cannot make the walk endless; the clip does the rest.
  const Eigen::Vector2i limit(4 * kMaxSidePixels, 4 * kMaxSidePixels);
  const Eigen::Vector2i from = pixelOf(a).cwiseMax(-limit).cwiseMin(limit);
  const Eigen::Vector2i to = pixelOf(b).cwiseMax(-limit).cwiseMin(limit);
  const int dx = std::abs(to.x() - from.x()), dy = -std::abs(to.y() - from.y());
  const int sx = from.x() < to.x() ? 1 : -1, sy = from.y() < to.y() ? 1 : -1;
  int col = from.x(), row = from.y(), error = dx + dy;
  while (true) {
    stamp(col, row, widthPixels, colour);
    if (col == to.x() && row == to.y()) return;
    const int twice = 2 * error;
    if (twice >= dy) {
      error += dy;
      col += sx;
    }
    if (twice <= dx) {
      error += dx;
      row += sy;
    }
  }
}

void MapCanvas::disc(const Eigen::Vector2d& centre, int radiusPixels, const Rgb& colour) {
  const Eigen::Vector2i c = pixelOf(centre);
  for (int dr = -radiusPixels; dr <= radiusPixels; ++dr)
    for (int dc = -radiusPixels; dc <= radiusPixels; ++dc)
      if (dc * dc + dr * dr <= radiusPixels * radiusPixels) setPixel(c.x() + dc, c.y() + dr, colour);
}

void MapCanvas::number(const Eigen::Vector2d& at, std::uint64_t number, int scale, int liftPixels,
                       const Rgb& colour) {
  const std::string digits = std::to_string(number);
  const int width = scale * (int(digits.size()) * (kDigitWidth + kDigitGap) - kDigitGap);
  const Eigen::Vector2i base = pixelOf(at);
  const int left = base.x() - width / 2, top = base.y() - liftPixels - scale * kDigitHeight;
  for (std::size_t k = 0; k < digits.size(); ++k) {
    const int x0 = left + int(k) * scale * (kDigitWidth + kDigitGap);
    for (int r = 0; r < kDigitHeight; ++r)
      for (int c = 0; c < kDigitWidth; ++c)
        if (kDigits[digits[k] - '0'][r] >> (kDigitWidth - 1 - c) & 1)
          for (int dr = 0; dr < scale; ++dr)
            for (int dc = 0; dc < scale; ++dc) setPixel(x0 + c * scale + dc, top + r * scale + dr, colour);
  }
}

}  // namespace rgnav
