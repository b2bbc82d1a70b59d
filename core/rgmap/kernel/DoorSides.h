// DoorSides: on which sides of a door line a region's robot stood, and from which sides it saw the
// door (ours). RegionModels.h uses both for the doors no region is attached to: such a door still
// separates two regions when one region's robot stayed on one side of it and another region saw
// it from the other side (Freiburg52: the door between two rooms whose regions were entered
// through the hallway; each room saw the other through it).
// A scan counts for a door if the sensor stood in front of it: at most depthM from its line,
// between its ends lengthened by widenM, and at least besideLineM off the line (on no side while
// on it). It saw the door if the beam towards the door's midpoint (or one of its two neighbours)
// ends no more than rangeToleranceM before the midpoint, or gives no return and the midpoint lies
// within the range that the freespace counts as free for such a beam (noReturnFreeRangeM, capped
// at the scan's maximum range as in regionBeams).
#pragma once

#include "core/rgmap/describe/GatewaySegment.h"
#include "core/rgmap/kernel/RgMapState.h"

namespace rgnav {

struct DoorSideProbe {
  double depthM = 8.0;             // a room's far end still counts (Freiburg52: 7.7 m)
  double widenM = 1.0;
  double besideLineM = 0.2;
  double rangeToleranceM = 0.15;
};

template <class V>
void describe(V& v, DoorSideProbe& c) {
  v.field("depth_m", c.depthM);
  v.field("widen_m", c.widenM);
  v.field("beside_line_m", c.besideLineM);
  v.field("range_tolerance_m", c.rangeToleranceM);
}

// Throws ConfigError for a negative or non-finite distance.
void validate(const DoorSideProbe& probe);

// Sides of the line from door.a to door.b (map frame): left (counter-clockwise of a -> b) and right.
enum DoorSides : unsigned { kNoSide = 0, kLeftSide = 1, kRightSide = 2, kBothSides = 3 };

// The sides of `door` on which some scan of `region` stood in front of it.
unsigned sidesStoodOn(const RgMapState& state, const Region& region, const GatewaySegment& door,
                      const DoorSideProbe& probe);
// The sides of `door` from which some scan of `region` in front of it saw its midpoint;
// `noReturnFreeRangeM` as the region freespace's (FreespaceConfig).
unsigned sidesSeenFrom(const RgMapState& state, const Region& region, const GatewaySegment& door,
                       const DoorSideProbe& probe, double noReturnFreeRangeM);

}  // namespace rgnav
