// RgMapEdits: the primitive changes of an RG Map (thesis 2.1: regions refer to their gateways and
// gateways to their regions; 6.1.1: merged regions, neutralised gateways). Each edit keeps the
// references both ways, re-flags the gateways it touches as neutralised or not, and appends its
// events to the state. The kernel's rules (RgMappingKernel.h) decide which edits to make; these
// functions assume valid IDs.
#pragma once

#include "core/rgmap/kernel/RgMapState.h"

namespace rgnav {

void emitEvent(RgMapState& state, RgMapEventKind kind, RegionId region, RegionId other, GatewayId gateway, DataId scan);

// A new region without scans, with its frame at `frame` (map frame). Event RegionCreated.
RegionId createRegion(RgMapState& state, const Pose2D& frame, DataId scan);

// A new gateway for the detector's `record`, placed with `odomToMap`, on no region yet; a narrow
// passage's sides get their crossing points 0 and 1. Event GatewayAdded.
GatewayId addGateway(RgMapState& state, const GatewayRecord& record, const Pose2D& odomToMap, DataId scan);

// Puts `region` on side `side` of gateway `g` (whose crossing point must be known). Events
// GatewayAttached, and GatewayNeutralised if both sides are now the same region. No-op if it is there.
void attachSide(RgMapState& state, GatewayId g, std::size_t side, RegionId region, DataId scan);

// Merges the two regions into the one with the lower ID: scans and gateways move over, the name
// of the lower one is kept (the other's if it has none), the current region follows. Events
// RegionsMerged, GatewayNeutralised for every gateway that now has it on both sides. Returns the
// merged region.
RegionId mergeRegions(RgMapState& state, RegionId a, RegionId b, DataId scan);

// Undoes the merge recorded in `merge` (RevertibleMerges.h; whyNotRevertible must have found it
// safe): the absorbed region is back with its ID, frame, name, scans, object names and the gateway
// sides that named it, the surviving region is as it was before the merge, and the scans stacked
// into the merged region since go with the region the robot was in when the merge was made (it
// is the current region again if it is the absorbed one). Gateways between the two are no longer
// neutralised. Event RegionsUnmerged. Returns the restored region.
RegionId unmergeRegions(RgMapState& state, const RevertibleMerge& merge, DataId scan);

// Moves the scans of region `from` with IDs in [first, end) to region `to`.
void moveScans(RgMapState& state, RegionId from, RegionId to, DataId first, DataId end);

// Removes a region (its sides of gateways become unknown again). Event RegionRemoved.
void removeRegion(RgMapState& state, RegionId region, DataId scan);

// Removes a gateway from the map and from its regions. Event GatewayDropped.
void dropGateway(RgMapState& state, GatewayId g, DataId scan);

}  // namespace rgnav
