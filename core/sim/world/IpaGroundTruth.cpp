// loadIpaGroundTruth: room components, separator blobs and their principal-axis segments.
#include "core/sim/world/IpaGroundTruth.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>

#include "core/raster/Components.h"
#include "core/raster/ImageFile.h"
#include "core/raster/ImageGrid.h"
#include "core/sim/world/FloorPlan.h"
#include "core/sim/world/GroundTruthAssembly.h"

namespace rgnav {
namespace {

// Per cell in grid order (row 0 at the bottom, so the image's rows flip): non-zero where the
// floor plan is free.
cv::Mat freeGridMask(const cv::Mat& image) {
  cv::Mat flipped;
  cv::flip(image, flipped, 0);
  return flipped >= kFloorPlanFreeGray;
}

// First and second moments of a blob's cell centres.
struct BlobMoments {
  double n = 0, x = 0, y = 0, xx = 0, xy = 0, yy = 0;
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
};

std::vector<DoorLine> separatorLines(const Components& blobs, const OccupancyGrid& grid) {
  std::vector<BlobMoments> m(static_cast<std::size_t>(blobs.count()));
  const auto forEachBlobCell = [&](auto visit) {
    for (int row = 0; row < grid.height(); ++row) {
      for (int col = 0; col < grid.width(); ++col) {
        const int blob = blobs.labels[static_cast<std::size_t>(row) * static_cast<std::size_t>(grid.width()) +
                                      static_cast<std::size_t>(col)];
        if (blob >= 0) visit(static_cast<std::size_t>(blob), grid.center({col, row}));
      }
    }
  };
  forEachBlobCell([&](std::size_t blob, WorldPoint p) {
    BlobMoments& b = m[blob];
    b.n += 1;
    b.x += p.x;
    b.y += p.y;
    b.xx += p.x * p.x;
    b.xy += p.x * p.y;
    b.yy += p.y * p.y;
  });
  std::vector<double> axisAngle(m.size());
  for (std::size_t i = 0; i < m.size(); ++i) {
    BlobMoments& b = m[i];
    b.x /= b.n;
    b.y /= b.n;
    const double cxx = b.xx / b.n - b.x * b.x, cxy = b.xy / b.n - b.x * b.y, cyy = b.yy / b.n - b.y * b.y;
    axisAngle[i] = 0.5 * std::atan2(2.0 * cxy, cxx - cyy);
  }
  forEachBlobCell([&](std::size_t blob, WorldPoint p) {
    BlobMoments& b = m[blob];
    const double s = (p.x - b.x) * std::cos(axisAngle[blob]) + (p.y - b.y) * std::sin(axisAngle[blob]);
    b.lo = std::min(b.lo, s);
    b.hi = std::max(b.hi, s);
  });
  std::vector<DoorLine> lines;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const double c = std::cos(axisAngle[i]), s = std::sin(axisAngle[i]);
    lines.push_back({{m[i].x + m[i].lo * c, m[i].y + m[i].lo * s}, {m[i].x + m[i].hi * c, m[i].y + m[i].hi * s}});
  }
  return lines;
}

}  // namespace

GroundTruth loadIpaGroundTruth(const std::string& gtPngPath, const std::string& emptyPngPath,
                               const OccupancyGrid& geometry) {
  const cv::Mat truthImage = readGrayImage(gtPngPath);
  requireSameSize(truthImage, gtPngPath, geometry);
  const cv::Mat emptyImage = readGrayImage(emptyPngPath);
  requireSameSize(emptyImage, emptyPngPath, geometry);

  const cv::Mat truthFree = freeGridMask(truthImage);
  const cv::Mat separators = freeGridMask(emptyImage) & ~truthFree;

  Components rooms = connectedComponents(truthFree, kIpaMinRoomPixels);
  GroundTruth truth = groundTruthFrame(geometry, std::move(rooms.labels), rooms.count());
  const Components blobs = connectedComponents(separators, kIpaMinSeparatorPixels);
  truth.doors = separatorLines(blobs, geometry);
  for (DoorLine& door : truth.doors) assignDoorRooms(truth, door, kIpaDoorProbeDistance);
  return truth;
}

}  // namespace rgnav
