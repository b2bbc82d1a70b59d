// Packed 1-bit freespace map; see FreespaceBitmap.h.
#include "core/rgmap/describe/FreespaceBitmap.h"

#include <bit>
#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

FreespaceBitmap FreespaceBitmap::allOccupied(double resolutionM, const Eigen::Vector2d& originM, int width,
                                             int height) {
  if (!(resolutionM > 0.0) || !std::isfinite(resolutionM) || !originM.allFinite() || width < 0 || height < 0)
    throw InvalidArgumentError("freespace bitmap: size must be >= 0, resolution positive, origin finite");
  const std::size_t cells = std::size_t(width) * std::size_t(height);
  return {resolutionM, originM, width, height, std::vector<std::uint8_t>((cells + 7) / 8, 0)};
}

void FreespaceBitmap::setFree(int col, int row) {
  const std::size_t k = std::size_t(row) * std::size_t(width) + std::size_t(col);
  bytes[k / 8] |= std::uint8_t(1u << (k % 8));
}

bool FreespaceBitmap::isFree(int col, int row) const {
  if (col < 0 || row < 0 || col >= width || row >= height) return false;
  const std::size_t k = std::size_t(row) * std::size_t(width) + std::size_t(col);
  return (bytes[k / 8] >> (k % 8)) & 1u;
}

bool FreespaceBitmap::isFreeAt(const Eigen::Vector2d& point) const {
  if (width == 0 || height == 0 || !point.allFinite()) return false;
  const Eigen::Vector2d cell = (point - originM) / resolutionM;
  if (cell.x() < 0.0 || cell.y() < 0.0 || cell.x() >= width || cell.y() >= height) return false;
  return isFree(int(cell.x()), int(cell.y()));
}

std::size_t FreespaceBitmap::freeCount() const {
  std::size_t n = 0;
  for (const std::uint8_t b : bytes) n += std::size_t(std::popcount(b));
  return n;
}

Eigen::Vector2d FreespaceBitmap::cellCenter(int col, int row) const {
  return originM + resolutionM * Eigen::Vector2d(col + 0.5, row + 0.5);
}

bool operator==(const FreespaceBitmap& a, const FreespaceBitmap& b) {
  return a.resolutionM == b.resolutionM && a.originM == b.originM && a.width == b.width && a.height == b.height &&
         a.bytes == b.bytes;
}

}  // namespace rgnav
