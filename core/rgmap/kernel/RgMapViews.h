// RgMapViews: what the RG Mapping Kernel module serves about its map (RGMappingKernel.idl), as
// plain values taken from the kernel: region summaries, a region with its line map and
// description (thesis table 2.1), gateways placed in the map frame, the RG graph and a path on
// it, the map's counts. The client library converts these to and from IDL types.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

#include "core/rgmap/describe/FreespaceBitmap.h"
#include "core/rgmap/describe/MainDirections.h"
#include "core/rgmap/graph/RgPathSearch.h"
#include "core/rgmap/kernel/RgMappingKernel.h"

namespace rgnav {

struct RegionSummaryView {
  RegionId id;
  std::string name;
  Pose2D frame;
  std::size_t scans = 0;
  bool finalised = false;
  std::vector<GatewayId> gateways;

  friend bool operator==(const RegionSummaryView&, const RegionSummaryView&) = default;
};

struct Segment2 {
  Eigen::Vector2d a = Eigen::Vector2d::Zero(), b = Eigen::Vector2d::Zero();

  friend bool operator==(const Segment2&, const Segment2&) = default;
};

// A rectangular 2D object of a region (RegionObjects.h), in the region frame.
struct RectangleObjectView {
  Pose2D pose;  // centre; theta: direction of the length axis, in [0, pi)
  double lengthM = 0.0, widthM = 0.0;
  double confidence = 0.0;  // share of the perimeter seen
  std::string name;         // semantic name; empty: none

  friend bool operator==(const RectangleObjectView&, const RectangleObjectView&) = default;
};

// Everything in the region frame.
struct RegionView {
  RegionSummaryView summary;
  std::vector<Segment2> lines;
  Eigen::Vector2d boxMin = Eigen::Vector2d::Zero(), boxMax = Eigen::Vector2d::Zero();
  FreespaceBitmap freespace;
  double areaM2 = 0.0;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  double majorAxisAngleRad = 0.0, majorVariance = 0.0, minorVariance = 0.0;
  std::vector<MainDirection> mainDirections;
  double accuracyInlierShare = 0.0, accuracyRmsM = 0.0, completeness = 0.0;
  std::vector<RectangleObjectView> objects;  // most confident first
};

// In the map frame.
struct GatewayView {
  GatewayId id;
  DetectorGatewayId detectorId;
  std::vector<ClassProbability> classes;
  bool door = false;
  bool neutralised = false;
  std::vector<Eigen::Vector2d> gatewayPoints, crossingPoints;
  RegionId sideA, sideB;
  std::size_t traversals = 0;
  // Side A's and side B's crossing point: indices into crossingPoints; kNoCrossing: not known yet.
  std::array<std::size_t, 2> sideCrossings{kNoCrossing, kNoCrossing};

  friend bool operator==(const GatewayView&, const GatewayView&) = default;
};

struct GraphNodeView {
  GatewayId gateway;
  std::size_t side = 0;  // 0 = A, 1 = B
  RegionId region;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();

  friend bool operator==(const GraphNodeView&, const GraphNodeView&) = default;
};

struct GraphEdgeView {
  std::size_t from = 0, to = 0;
  GatewayId gateway;  // a gateway edge's gateway; none for a region edge
  RegionId region;    // a region edge's region; none for a gateway edge
  double lengthM = 0.0, costM = 0.0;

  bool throughGateway() const { return !gateway.isNone(); }

  friend bool operator==(const GraphEdgeView&, const GraphEdgeView&) = default;
};

struct GraphView {
  std::vector<GraphNodeView> nodes;
  std::vector<GraphEdgeView> edges;
};

struct PathView {
  std::vector<GraphNodeView> crossings;
  double costM = 0.0, lengthM = 0.0;
};

struct MapSummaryView {
  std::size_t regions = 0, gateways = 0, neutralised = 0;
  std::size_t hypotheses = 0;  // gateways without a region yet (Gateway::inMap), not in `gateways`
  DataId lastScan = 0;
  RgMapEventId lastEvent = 0;
  RegionId current;
  bool endOfData = false;

  friend bool operator==(const MapSummaryView&, const MapSummaryView&) = default;
};

struct RgMapEventBatch {
  std::vector<RgMapEvent> events;
  RgMapEventId latestId = 0;
  DataId lastScan = 0;
  bool endOfData = false;
};

RegionSummaryView summaryOf(const Region& region);
// Throws NotAvailableError for an unknown region.
RegionView regionView(const RgMappingKernel& kernel, RegionId region);
std::vector<GatewayView> gatewayViews(const RgMappingKernel& kernel);
GraphNodeView nodeView(const RgNode& node);
GraphView graphView(const RgGraph& graph);
PathView pathView(const RgPath& path);
// endOfData is the caller's to set.
MapSummaryView mapSummary(const RgMappingKernel& kernel);

}  // namespace rgnav
