// Rectangles of a region's line map that are objects; see RegionObjects.h.
#include "core/rgmap/describe/RegionObjects.h"

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

// The share of the freespace cells whose centres lie in `outline` (convex, counter-clockwise)
// that are free; 0 if no centre does.
double seenFreeShare(const Polygon& outline, const FreespaceBitmap& map) {
  if (map.width <= 0 || map.height <= 0) return 0.0;
  Eigen::Vector2d lo = outline.front(), hi = lo;
  for (const Eigen::Vector2d& p : outline) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const auto index = [&](double v, double origin) { return int(std::floor((v - origin) / map.resolutionM)); };
  const int c0 = std::max(0, index(lo.x(), map.originM.x())), c1 = std::min(map.width - 1, index(hi.x(), map.originM.x()));
  const int r0 = std::max(0, index(lo.y(), map.originM.y())), r1 = std::min(map.height - 1, index(hi.y(), map.originM.y()));
  std::size_t inside = 0, free = 0;
  for (int row = r0; row <= r1; ++row)
    for (int col = c0; col <= c1; ++col) {
      if (!insideConvex(outline, map.cellCenter(col, row), 0.0)) continue;
      ++inside;
      if (map.isFree(col, row)) ++free;
    }
  return inside == 0 ? 0.0 : double(free) / double(inside);
}

}  // namespace

RectangleDetectorParams openCornerRectangles() {
  RectangleDetectorParams params;
  params.grouping.restrictive = false;
  params.minConfidence = 0.45;
  return params;
}

std::vector<Rectangle2D> detectRegionObjects(const std::vector<LineSegment>& lines, const FreespaceBitmap& freespace,
                                             const RegionObjectParams& params) {
  if (!(params.maxSeenFreeShare >= 0.0 && params.maxSeenFreeShare <= 1.0) || !(params.maxAspectRatio >= 1.0) ||
      !(params.minWidthM >= 0.0 && params.maxWidthM >= params.minWidthM))
    throw InvalidArgumentError(
        "region objects: maxSeenFreeShare must lie in [0, 1], maxAspectRatio >= 1, 0 <= minWidthM <= maxWidthM");
  return RectangleDetector(params.rectangles).detect(lines, [&](const Rectangle2D& r) {
    return r.lengthM <= params.maxAspectRatio * r.widthM && r.widthM >= params.minWidthM &&
           r.widthM <= params.maxWidthM && seenFreeShare(rectangleOutline(r), freespace) <= params.maxSeenFreeShare;
  });
}

}  // namespace rgnav
