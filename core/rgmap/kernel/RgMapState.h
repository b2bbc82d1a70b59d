// RgMapState: the whole state of the RG Mapping Kernel (thesis 2.1, 2.2, 5.2) as plain data: the
// RG Map <R, G> with its regions <M, O, P, G_ref> and gateways <M, P, R_ref>, the aligned scans
// the region descriptions are computed from, the map's event list and the learned costs of the
// RG Graph. Everything else the kernel holds (line maps, descriptions) is derived from this and
// recomputed on demand, so this struct is exactly what a checkpoint holds (RgMapCodec.h) and what
// the consistency check inspects (RgMapConsistency.h).
// Frames: every position is kept in the map frame of the corrected scans. A region's frame is a
// pose in the map frame (the robot pose where the region was created); positions in a region's
// frame are derived (inverse(frame) applied to the map position), so merging two regions needs
// no re-expression of stored data: the merged region keeps the frame of the lower ID and the
// composition happens when region-frame geometry is derived.
// Deliberate differences: the thesis stores coordinate transformations between regions in the
// gateways; with one SLAM map frame, the transform between two regions is between(frameA,
// frameB). Objects (O) are derived from the line map like the description (RegionModels.h); the
// state keeps only their names (ObjectNames.h).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/common/SensorData.h"
#include "core/gateways/detection/GatewayRecord.h"
#include "core/rgmap/graph/EdgeCostTable.h"
#include "core/rgmap/kernel/RgMapEvent.h"

namespace rgnav {

// IDs of the kernel's regions and gateways start at 1; 0 means "none". A gateway's kernel ID is
// not the detector's ID (GatewayRecord::id): the kernel numbers gateways as it takes them in.

inline constexpr std::size_t kNoCrossing = std::numeric_limits<std::size_t>::max();

// One side of a gateway (thesis 2.1.3: each side has one crossing point and lies in one region).
struct GatewaySideRef {
  RegionId region;                 // 0: no region known on this side yet
  std::size_t crossing = kNoCrossing;  // index into record.crossingPoints; kNoCrossing: not known yet
  DataId attachedAt = 0;               // the scan at which `region` was attached

  friend bool operator==(const GatewaySideRef&, const GatewaySideRef&) = default;
};

inline constexpr std::size_t kSideA = 0, kSideB = 1;

struct Gateway {
  GatewayId id;
  // The detector's hypothesis as last reported (detector ID, class label and probabilities, gateway
  // and crossing points, width), in the detector's odometry frame ...
  GatewayRecord record;
  // ... and the transform that places it into the map frame: corrected(lastScan) ∘ odometry(lastScan)^-1.
  Pose2D odomToMap;
  // Side A and side B. A narrow passage's sides are its crossing points 0 and 1; a hallway area's
  // side A is the side its first traversal started from, side B the side that traversal went to
  // (areas get their sides from traversals only, RgMappingKernel.h).
  std::array<GatewaySideRef, 2> sides;
  std::array<std::size_t, 2> traversalsFrom{};  // traversals that started on side A / side B
  bool neutralised = false;                     // the same region on both sides (thesis 6.1.1)
  // Further detector IDs of the same door: a track the detector started anew for a door it had
  // reported before (its odometry drifted, or it had lost the first track); see
  // RgMappingKernel.h. Their records are not kept: the first record stays this gateway's geometry.
  std::vector<DetectorGatewayId> aliases;

  bool door() const { return record.kind == GatewayKind::NarrowPassage; }
  // A gateway of the map joins at least one region; one with no region on either side (detected,
  // never traversed, e.g. a turn the robot only saw) is still a hypothesis.
  bool inMap() const { return !sides[0].region.isNone() || !sides[1].region.isNone(); }

  friend bool operator==(const Gateway&, const Gateway&) = default;
};

struct Region {
  RegionId id;
  Pose2D frame;                  // the region's own frame, in the map frame
  std::vector<DataId> scans;     // the scans taken in it, ascending
  std::set<GatewayId> gateways;  // G_ref: every gateway with this region on a side
  std::string name;              // semantic name; empty: none
  bool finalised = false;        // left at least once, so it has a final description
  // Names of its objects: name -> the named object's centre in the map frame (ObjectNames.h).
  std::map<std::string, Eigen::Vector2d> objectNames;

  friend bool operator==(const Region&, const Region&) = default;
};

// An aligned scan: the scan as the laser gave it and the corrected pose of the sensor in the map frame.
struct StoredScan {
  LaserScan scan;
  Pose2D corrected;

  friend bool operator==(const StoredScan&, const StoredScan&) = default;
};

// A merge on request that can still be undone (RgMappingKernel::unmergeRegions, RevertibleMerges.h):
// the two regions as they were before it, the regions on the sides of their gateways then, and
// where the robot was. Region IDs are never given again, so the absorbed region's ID stays free.
struct RevertibleMerge {
  Region kept;      // the region that survived the merge (the lower ID), before it
  Region absorbed;  // the region merged into it, before it
  // The regions on side A and side B of every gateway of either region, before the merge.
  std::map<GatewayId, std::array<RegionId, 2>> sides;
  RegionId current;        // the robot's region when the merge was made ...
  DataId visitStart = 0;   // ... and the first scan of that visit
  DataId lastScan = 0;     // the last scan taken in then: scans after it were stacked since

  friend bool operator==(const RevertibleMerge&, const RevertibleMerge&) = default;
};

struct RgMapState {
  std::map<RegionId, Region> regions;
  std::map<GatewayId, Gateway> gateways;
  std::map<DataId, StoredScan> scans;
  std::vector<RgMapEvent> events;  // consecutive IDs from 1
  RegionId current;            // the region the robot is in; 0 before the first input
  DataId visitStart = 0;           // the first scan of the robot's current visit of `current`
  RegionId nextRegionId{1};
  GatewayId nextGatewayId{1};
  DataId lastScanId = 0;                  // the last scan taken in (inputs resume after it)
  GatewayEventId lastGatewayEventId = 0;  // the last gateway event taken in
  std::uint64_t lastPoseRevision = 0;     // the last SLAM pose revision applied (revisePoses)
  // The learned costs of the RG Graph (EdgeCostTable.h).
  std::map<EdgeKey, TraversalStats> edgeTraversals;
  std::map<GatewayId, double> doorOffsets;
  // The latest merges on request, oldest first, at most RgMappingKernelConfig::revertibleMerges.
  std::vector<RevertibleMerge> revertibleMerges;
};

}  // namespace rgnav
