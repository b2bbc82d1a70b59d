// DoorSeparation: whether a narrow passage of the RG Map really separates two places (ours; thesis
// 4.2.1 defines a door by the narrow passage alone, and 6.1.1 leaves wrong gateways to later
// consistency checks). A door in a wall is the only way between its two sides nearby; a "door"
// between a pillar and a wall, or between a cabinet's corner and a desk, has free floor around its
// ends. The test:
//   - the scans taken within radiusM + scanMarginM of the door's midpoint are ray-cast into a
//     local occupancy grid (RegionFreespace: free, occupied, unknown; beams end at the border of
//     that square);
//   - a cell is passable if it is free and none of its eight neighbours is occupied (a gap the
//     laser sees through between two obstacles one cell apart is no way around);
//   - the door blocks a slab: its line lengthened by overhangM into its jambs, slabHalfDepthM deep
//     on either side. A door's line does not lie exactly in its wall: the tracker averages the
//     gateway points seen from both faces of the wall, and the placement carries the SLAM error
//     (office_c: door lines 0.3 m beside the gap in a thin wall, and a path through the gap
//     "went around" the line). The doors between two regions within radiusM block theirs as well;
//   - the door separates unless a 4-connected path of passable cells within radiusM of the
//     midpoint joins the cells seedOffsetM beyond the slab in front of and behind the midpoint.
// Without evidence (a seed cell not passable) a door separates: the test only takes doors away.
// The same test for a hallway area (ours; thesis 4.1 classifies a hallway area from what the
// laser sees of it, and a room's corner or a gap between desks can look like a junction): the
// area's square, grown by overhangM, blocks the way; the two sides the robot went between are
// separated unless a way within radiusM of the square (the square's own reach plus radiusM from
// its centre) joins the cells just beyond the grown square (overhangM, half a cell, seedOffsetM and
// a cell) outward from those sides' crossing points. In a real junction
// the arms meet only in the square; in a room there is floor around it.
#pragma once

#include <cstddef>

#include "core/rgmap/kernel/RgMapState.h"

namespace rgnav {

struct DoorSeparationConfig {
  double cellSizeM = 0.1;
  double radiusM = 2.0;         // a way around must stay this close to the door's midpoint
  double scanMarginM = 1.0;     // scans taken this much farther away also count
  double slabHalfDepthM = 0.35; // a door blocks this far on either side of its line ...
  double overhangM = 0.2;       // ... and this far beyond each gateway point
  double seedOffsetM = 0.2;     // the ends of the way: this far beyond the slab
};

template <class V>
void describe(V& v, DoorSeparationConfig& c) {
  v.field("cell_size_m", c.cellSizeM);
  v.field("radius_m", c.radiusM);
  v.field("scan_margin_m", c.scanMarginM);
  v.field("slab_half_depth_m", c.slabHalfDepthM);
  v.field("overhang_m", c.overhangM);
  v.field("seed_offset_m", c.seedOffsetM);
}

// Throws ConfigError for a non-positive or non-finite size.
void validate(const DoorSeparationConfig& config);

// Whether door `id` of `state` separates its two sides (see above). `id` must be a narrow passage.
bool separatesSpace(const RgMapState& state, GatewayId id, const DoorSeparationConfig& config);

// Whether hallway area `id` separates the sides of its crossing points `fromCrossing` and
// `toCrossing` (indices into its record's crossing points; see above).
bool areaSeparatesSides(const RgMapState& state, GatewayId id, std::size_t fromCrossing, std::size_t toCrossing,
                        const DoorSeparationConfig& config);

}  // namespace rgnav
