// Regions grown into the unclaimed free cells along their walls (see RegionGrowth.h).
#include "tests/eval/rooms/RegionGrowth.h"

#include <deque>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {

void growIntoUnclaimed(std::span<RegionRaster> regions, std::span<const std::uint8_t> mapFree, int width, int height,
                       int maxGrowCells) {
  if (width < 0 || height < 0 || maxGrowCells < 0)
    throw InvalidArgumentError("growIntoUnclaimed: negative map size or growth");
  const std::size_t cells = std::size_t(width) * std::size_t(height);
  if (mapFree.size() != cells) throw InvalidArgumentError("growIntoUnclaimed: the free map has the wrong size");
  std::vector<std::uint8_t> unclaimed(mapFree.begin(), mapFree.end());
  for (const RegionRaster& region : regions) {
    if (region.claimed.size() != cells)
      throw InvalidArgumentError("growIntoUnclaimed: region " + std::to_string(region.regionId) +
                                 " has a raster of the wrong size");
    for (std::size_t i = 0; i < cells; ++i)
      if (region.claimed[i] != 0) unclaimed[i] = 0;
  }
  std::vector<int> steps(cells);
  for (RegionRaster& region : regions) {
    std::deque<std::size_t> front;
    for (std::size_t i = 0; i < cells; ++i) {
      steps[i] = region.claimed[i] != 0 ? 0 : -1;
      if (region.claimed[i] != 0) front.push_back(i);
    }
    while (!front.empty()) {
      const std::size_t cell = front.front();
      front.pop_front();
      if (steps[cell] >= maxGrowCells) continue;
      const int col = int(cell % std::size_t(width)), row = int(cell / std::size_t(width));
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const int c = col + dc, r = row + dr;
          if (c < 0 || r < 0 || c >= width || r >= height) continue;
          const std::size_t next = std::size_t(r) * std::size_t(width) + std::size_t(c);
          if (unclaimed[next] == 0 || steps[next] >= 0) continue;
          steps[next] = steps[cell] + 1;
          region.claimed[next] = 1;
          front.push_back(next);
        }
    }
  }
}

}  // namespace rgnav
