// Regions as floor-plan pixel sets; see RegionPixels.h.
#include "tests/eval/rooms/RegionPixels.h"

#include <cmath>

#include "core/common/Errors.h"
#include "core/rgmap/describe/FreespaceRaster.h"
#include "tests/eval/rooms/RegionGrowth.h"
#include "tests/eval/rooms/RegionHoles.h"

namespace rgnav {

std::vector<SegmentPixels> regionPixels(const FinalMap& map, const Pose2D& mapToWorld, const OccupancyGrid& world,
                                        double growM, double maxHoleM2) {
  if (!(maxHoleM2 >= 0.0) || !std::isfinite(maxHoleM2))
    throw InvalidArgumentError("regionPixels: the largest hole must be a finite area >= 0");
  const RasterFrame frame{world.resolution(), {world.origin().x, world.origin().y}, world.width(), world.height()};
  std::vector<std::uint8_t> free;
  for (const Cell cell : world.cells()) free.push_back(cell == Cell::Free ? 1 : 0);
  std::vector<RegionRaster> rasters;
  for (const RegionView& region : map.regions) {
    RegionRaster raster{std::int64_t(region.summary.id.value()),
                        rasteriseFreespace(region.freespace, compose(mapToWorld, region.summary.frame), frame)};
    for (std::size_t i = 0; i < free.size(); ++i) raster.claimed[i] &= free[i];
    rasters.push_back(std::move(raster));
  }
  growIntoUnclaimed(rasters, free, world.width(), world.height(),
                    int(std::floor(growM / world.resolution() + 1e-9)));
  fillEnclosedHoles(rasters, world.width(), world.height(),
                    std::size_t(std::floor(maxHoleM2 / (world.resolution() * world.resolution()))));
  std::vector<SegmentPixels> out;
  for (const RegionRaster& raster : rasters) {
    SegmentPixels segment{std::uint64_t(raster.regionId), {}};
    for (std::size_t i = 0; i < raster.claimed.size(); ++i)
      if (raster.claimed[i] != 0) segment.pixels.push_back(i);
    out.push_back(std::move(segment));
  }
  return out;
}

}  // namespace rgnav
