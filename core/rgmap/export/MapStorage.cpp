// Bytes of an RG Map against an occupancy grid; see MapStorage.h.
#include "core/rgmap/export/MapStorage.h"

#include <cmath>

#include "core/common/Errors.h"
#include "core/rgmap/export/MapExtent.h"

namespace rgnav {
namespace {

constexpr std::size_t kFrameBytes = 12, kSegmentBytes = 16, kPointBytes = 8;

}  // namespace

MapStorage mapStorage(const RgMapSnapshot& map, double gridResolutionM) {
  if (!std::isfinite(gridResolutionM) || !(gridResolutionM > 0.0))
    throw InvalidArgumentError("map storage: the grid resolution must be positive");
  MapStorage out;
  for (const RegionSnapshot& r : map.regions)
    out.rgMapBytes += kFrameBytes + r.description.freespaceBytes() + kSegmentBytes * r.lines.size();
  for (const GatewaySnapshot& g : map.gateways)
    out.rgMapBytes += kPointBytes * (g.inMap.gatewayPoints.size() + g.inMap.crossingPoints.size());
  const Eigen::AlignedBox2d extent = mapExtent(map);
  if (!extent.isEmpty()) {
    const Eigen::Vector2d cells = (extent.sizes() / gridResolutionM).array().ceil();
    out.occupancyGridBytes = std::size_t(cells.x()) * std::size_t(cells.y());
  }
  return out;
}

}  // namespace rgnav
