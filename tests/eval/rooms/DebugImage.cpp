// The room evaluation's debug pictures; see DebugImage.h.
#include "tests/eval/rooms/DebugImage.h"

#include "core/lines/ScanPoints.h"
#include "core/raster/ImageFile.h"
#include "core/rgmap/export/MapCanvas.h"
#include "tests/eval/rooms/ObjectScoring.h"

namespace rgnav {
namespace {

constexpr Rgb kBlocked{90, 90, 90};
constexpr Rgb kUncovered{230, 0, 0};
constexpr Rgb kSeparator{0, 0, 0};
constexpr Rgb kScanPosition{0, 0, 0};

Rgb darkened(const Rgb& c) {
  return {std::uint8_t(c.r * 3 / 5), std::uint8_t(c.g * 3 / 5), std::uint8_t(c.b * 3 / 5)};
}

// The picture of `regions` over the floor plan, without the scan positions.
MapCanvas drawRegions(const OccupancyGrid& world, const GroundTruth& truth, const FinalMap& map,
                      const Pose2D& mapToWorld, std::span<const SegmentPixels> regions) {
  const Eigen::Vector2d origin(world.origin().x, world.origin().y);
  const Eigen::AlignedBox2d extent(origin, origin + world.resolution() * Eigen::Vector2d(world.width(), world.height()));
  MapCanvas canvas(extent, world.resolution(), kBackgroundColour);
  const auto width = std::size_t(world.width());
  const auto paint = [&](std::size_t pixel, const Rgb& colour) {
    canvas.setPixel(int(pixel % width), world.height() - 1 - int(pixel / width), colour);
  };

  std::vector<std::uint8_t> claims(world.cells().size(), 0);
  for (const SegmentPixels& region : regions)
    for (const std::size_t pixel : region.pixels) claims[pixel] = std::uint8_t(std::min(claims[pixel] + 1, 2));
  for (std::size_t pixel = 0; pixel < claims.size(); ++pixel) {
    if (world.cells()[pixel] != Cell::Free)
      paint(pixel, kBlocked);
    else if (claims[pixel] == 0 && truth.labels[pixel] >= 0)
      paint(pixel, kUncovered);
  }
  for (const SegmentPixels& region : regions) {
    const Rgb colour = regionColour(RegionId(region.id));
    for (const std::size_t pixel : region.pixels) paint(pixel, claims[pixel] > 1 ? darkened(colour) : colour);
  }
  for (const DoorLine& door : truth.doors) canvas.line({door.a.x, door.a.y}, {door.b.x, door.b.y}, kSeparator, 1);
  for (const GatewayView& g : map.gateways) {
    const Rgb colour = gatewayColour(g.door, g.neutralised);
    for (std::size_t i = 0; i < g.gatewayPoints.size(); ++i) {
      const Eigen::Vector2d a = transformPoint(mapToWorld, g.gatewayPoints[i]);
      const Eigen::Vector2d b = transformPoint(mapToWorld, g.gatewayPoints[(i + 1) % g.gatewayPoints.size()]);
      if (g.gatewayPoints.size() > 2 || i == 0) canvas.line(a, b, colour, 3);
    }
  }
  for (const RegionView& region : map.regions)
    for (const RectangleObjectView& o : region.objects) {
      const Polygon outline = objectOutlineInWorld(region, o, mapToWorld);
      for (std::size_t i = 0; i < outline.size(); ++i) canvas.line(outline[i], outline[(i + 1) % outline.size()], kObjectColour, 2);
    }
  for (const SegmentPixels& region : regions) {
    if (region.pixels.empty()) continue;
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (const std::size_t pixel : region.pixels) sum += Eigen::Vector2d(double(pixel % width), double(pixel / width));
    const Eigen::Vector2d centre =
        origin + world.resolution() * (sum / double(region.pixels.size()) + Eigen::Vector2d(0.5, 0.5));
    canvas.number(centre, region.id, 2, 0, kLabelColour);
  }
  return canvas;
}

}  // namespace

void writeRoomImage(const std::string& path, const OccupancyGrid& world, const GroundTruth& truth,
                    const FinalMap& map, const Pose2D& mapToWorld, std::span<const SegmentPixels> regions) {
  writeImage(path, drawRegions(world, truth, map, mapToWorld, regions).image());
}

void writeRegionImage(const std::string& path, const OccupancyGrid& world, const GroundTruth& truth,
                      const FinalMap& map, const Pose2D& mapToWorld, const SegmentPixels& region,
                      std::span<const Eigen::Vector2d> scanPositions) {
  MapCanvas canvas = drawRegions(world, truth, map, mapToWorld, std::span<const SegmentPixels>(&region, 1));
  for (const Eigen::Vector2d& p : scanPositions) {
    const Eigen::Vector2i pixel = canvas.pixelOf(p);
    canvas.setPixel(pixel.x(), pixel.y(), kScanPosition);
  }
  writeImage(path, canvas.image());
}

}  // namespace rgnav
