// RgMapSnapshot: an RG Map as plain data at one moment, for its exports (JSON, SVG, PNG): the
// regions with their metric description M, objects O and properties P (thesis 2.1.1: line map
// and region description with its 2D objects, all in the region's own frame), the gateways placed
// into the map frame (2.1.2) and the RG Graph (2.1.3). The kernel computes line maps and
// descriptions on demand; a snapshot asks for every one once, so the exporters need no kernel,
// work on the same data, and tests can build snapshots by hand.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/rgmap/kernel/RgMappingKernel.h"

namespace rgnav {

struct RegionSnapshot {
  Region region;                   // ID, frame (map frame), scans, gateways, name, finalised
  std::vector<LineSegment> lines;  // the 2D line segment map, region frame
  RegionDescription description;   // region frame

  // A point of the region frame in the map frame.
  Eigen::Vector2d toMap(const Eigen::Vector2d& p) const;
  // Where the region's label goes, in the map frame: the freespace centroid if it lies in a free
  // cell, else the centre of the free cell nearest to it (a ring corridor's centroid lies in the
  // block it runs around), preferring cells with free cells all around them up to two cells
  // away; the frame's origin for a region without free cells.
  Eigen::Vector2d labelPosition() const;
};

struct GatewaySnapshot {
  Gateway gateway;     // as the state holds it (record in the detector's odometry frame)
  PlacedGateway inMap;  // its gateway and crossing points in the map frame

  std::size_t traversals() const { return gateway.traversalsFrom[0] + gateway.traversalsFrom[1]; }
};

struct RgMapSnapshot {
  std::vector<RegionSnapshot> regions;    // ascending ID
  std::vector<GatewaySnapshot> gateways;    // the map's (Gateway::inMap), ascending ID
  std::vector<GatewaySnapshot> hypotheses;  // detected gateways no region has taken in, ascending ID
  std::vector<RgNode> graphNodes;         // RgGraph::nodes(), map frame
  std::vector<RgEdge> graphEdges;         // RgGraph::edges()
  std::size_t scanCount = 0;              // aligned scans the map holds
  DataId lastScanId = 0;
  RgMapEventId lastEventId = 0;
  RegionId currentRegion;  // 0 before the first input
};

// Throws what RgMappingKernel::lineMap and description throw for a region that cannot be
// described (InvalidArgumentError for one wider than the freespace grid's maximum extent).
RgMapSnapshot snapshotOf(const RgMappingKernel& kernel);

}  // namespace rgnav
