// A kernel's RG Map as plain data; see RgMapSnapshot.h.
#include "core/rgmap/export/RgMapSnapshot.h"

#include <optional>

#include "core/lines/ScanPoints.h"

namespace rgnav {
namespace {

constexpr int kLabelClearanceCells = 2;

}  // namespace

Eigen::Vector2d RegionSnapshot::toMap(const Eigen::Vector2d& p) const { return transformPoint(region.frame, p); }

Eigen::Vector2d RegionSnapshot::labelPosition() const {
  const FreespaceBitmap& free = description.freespace;
  const Eigen::Vector2d& centroid = description.moments.centroid;
  if (free.isFreeAt(centroid)) return toMap(centroid);
  // Every cell within `radius` cells of (col, row) is free.
  const auto clear = [&free](int col, int row, int radius) {
    for (int dr = -radius; dr <= radius; ++dr)
      for (int dc = -radius; dc <= radius; ++dc)
        if (!free.isFree(col + dc, row + dr)) return false;
    return true;
  };
  // Rather a cell well inside the freespace than one at its edge, where the label would cover a wall.
  for (int radius = kLabelClearanceCells; radius >= 0; --radius) {
    std::optional<Eigen::Vector2d> nearest;
    for (int row = 0; row < free.height; ++row)
      for (int col = 0; col < free.width; ++col) {
        const Eigen::Vector2d c = free.cellCenter(col, row);
        if (clear(col, row, radius) && (!nearest || (c - centroid).norm() < (*nearest - centroid).norm()))
          nearest = c;
      }
    if (nearest) return toMap(*nearest);
  }
  return toMap(Eigen::Vector2d::Zero());
}

RgMapSnapshot snapshotOf(const RgMappingKernel& kernel) {
  const RgMapState& state = kernel.state();
  RgMapSnapshot out;
  for (const auto& [id, region] : state.regions)
    out.regions.push_back({region, kernel.lineMap(id).lines(), kernel.description(id)});
  for (const auto& [id, gateway] : state.gateways)
    (gateway.inMap() ? out.gateways : out.hypotheses).push_back({gateway, placeGateway(gateway)});
  const RgGraph graph = kernel.graph();
  out.graphNodes = graph.nodes();
  out.graphEdges = graph.edges();
  out.scanCount = state.scans.size();
  out.lastScanId = state.lastScanId;
  out.lastEventId = state.events.empty() ? 0 : state.events.back().id;
  out.currentRegion = state.current;
  return out;
}

}  // namespace rgnav
