// RgMapEvent: one change of the RG Map (thesis 2.2, 5.2, 6.1.1), with an ID. The kernel keeps
// every event in its state, with consecutive IDs from 1, so that consumers (localisation, path
// planning, the GUI) follow the map's changes by ID like any other data stream.
// Stacking a scan into the current region is no event: the preliminary description changes with
// every scan, and RgMapState::lastScanId tells how far the map has come.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "core/common/SensorData.h"
#include "core/rgmap/graph/RgGraphKeys.h"

namespace rgnav {

using RgMapEventId = std::uint64_t;

enum class RgMapEventKind : std::uint8_t {
  RegionCreated,       // region: the new region (the robot is in it)
  RegionEntered,       // region: a known region the robot entered again (a revisit)
  RegionFinalised,     // region: left for the first time; its description is final
  RegionUpdated,       // region: left again after a revisit; its description was updated
  RegionsMerged,       // region: the merged region (the lower ID), other: the region merged into it
  RegionsUnmerged,     // region: a merged region back as before a merge on request, other: the region restored
  RegionRemoved,       // region: a region left without a single scan in it
  RegionNamed,         // region
  ObjectNamed,         // region: the region of the named object
  GatewayAdded,        // gateway: a new gateway hypothesis
  GatewayUpdated,      // gateway: new geometry or class probabilities from the detector
  GatewayAttached,     // gateway, region: now on one of its sides; other: the region it replaced
  GatewayTraversed,    // gateway, region: left behind, other: entered
  GatewayNeutralised,  // gateway, region: the region on both of its sides
  GatewayRepaired,     // gateway: missed on an earlier traversal; region: split at scanId, other: the part split off
  GatewayDropped,      // gateway: no transition after all (Deadend, Hallway) and never traversed
  PosesRevised,        // corrected poses of stored scans changed (SLAM)
  CostsLearned,        // the RG Graph learned an edge traversal or a door state
};

struct RgMapEvent {
  RgMapEventId id = 0;
  RgMapEventKind kind = RgMapEventKind::RegionCreated;
  RegionId region;
  RegionId other;
  GatewayId gateway;
  DataId scanId = 0;  // the scan the change refers to (the input's scan)

  friend bool operator==(const RgMapEvent&, const RgMapEvent&) = default;
};

// "RegionCreated", ...: for checkpoints and messages.
std::string_view eventKindName(RgMapEventKind kind);
// The kind named `name`, or nullopt.
std::optional<RgMapEventKind> parseEventKind(std::string_view name);

}  // namespace rgnav
