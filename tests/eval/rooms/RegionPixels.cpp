// Regions as floor-plan pixel sets; see RegionPixels.h.
#include "tests/eval/rooms/RegionPixels.h"

#include "core/rgmap/describe/FreespaceRaster.h"

namespace rgnav {

std::vector<SegmentPixels> regionPixels(const FinalMap& map, const Pose2D& mapToWorld, const OccupancyGrid& world) {
  const RasterFrame frame{world.resolution(), {world.origin().x, world.origin().y}, world.width(), world.height()};
  const std::vector<Cell>& cells = world.cells();
  std::vector<SegmentPixels> out;
  for (const RegionView& region : map.regions) {
    const std::vector<std::uint8_t> raster =
        rasteriseFreespace(region.freespace, compose(mapToWorld, region.summary.frame), frame);
    SegmentPixels segment{region.summary.id, {}};
    for (std::size_t i = 0; i < raster.size(); ++i)
      if (raster[i] != 0 && cells[i] == Cell::Free) segment.pixels.push_back(i);
    out.push_back(std::move(segment));
  }
  return out;
}

}  // namespace rgnav
