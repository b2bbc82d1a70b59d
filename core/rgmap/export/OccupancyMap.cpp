// The global occupancy grid of an RG Map's scans; see OccupancyMap.h.
#include "core/rgmap/export/OccupancyMap.h"

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"
#include "core/rgmap/describe/RegionFreespace.h"

namespace rgnav {
namespace {

Cell cellOf(FreespaceCell c) {
  switch (c) {
    case FreespaceCell::Free: return Cell::Free;
    case FreespaceCell::Occupied: return Cell::Occupied;
    case FreespaceCell::Unknown: break;
  }
  return Cell::Unknown;
}

}  // namespace

OccupancyGrid occupancyMapOf(const RgMapState& state, const OccupancyMapConfig& config) {
  if (!std::isfinite(config.resolutionM) || !(config.resolutionM > 0.0))
    throw ConfigError("occupancy map: resolutionM must be positive");
  if (state.scans.empty()) throw NotAvailableError("occupancy map: the RG Map holds no scan");
  RegionFreespace counts({config.resolutionM, config.noReturnFreeRangeM, kMaxOccupancyCells * config.resolutionM,
                          config.freePerHit});
  for (const auto& [id, stored] : state.scans) counts.addScan(stored.scan, stored.corrected, {});

  // Crop to the cells any beam reached.
  const CellWindow& w = counts.window();
  int iMin = w.col0 + w.width, iMax = w.col0 - 1, jMin = w.row0 + w.height, jMax = w.row0 - 1;
  for (int j = w.row0; j < w.row0 + w.height; ++j)
    for (int i = w.col0; i < w.col0 + w.width; ++i)
      if (counts.cell(i, j) != FreespaceCell::Unknown) {
        iMin = std::min(iMin, i);
        iMax = std::max(iMax, i);
        jMin = std::min(jMin, j);
        jMax = std::max(jMax, j);
      }
  if (iMax < iMin) throw NotAvailableError("occupancy map: no beam of the RG Map's scans reached a cell");
  OccupancyGrid grid(iMax - iMin + 1, jMax - jMin + 1, config.resolutionM,
                     {iMin * config.resolutionM, jMin * config.resolutionM}, Cell::Unknown);
  for (int j = jMin; j <= jMax; ++j)
    for (int i = iMin; i <= iMax; ++i) grid.set({i - iMin, j - jMin}, cellOf(counts.cell(i, j)));
  return grid;
}

MapServerFiles exportOccupancyMap(const std::string& dir, const std::string& name, const RgMapState& state,
                                  const OccupancyMapConfig& config) {
  return writeMapServerMap(dir, name, occupancyMapOf(state, config));
}

}  // namespace rgnav
