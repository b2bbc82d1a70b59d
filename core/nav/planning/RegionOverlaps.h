// RegionOverlaps: where two regions' planning grids are both free at the same place of the map
// frame, one transfer point per connected piece of such space: the robot standing there stands
// in both regions, so a route may pass from one to the other there, whether or not a gateway was
// detected between them (ours; the thesis passes between regions only at the crossing points of
// gateways, so a passage the gateway detection missed is no route at all, while a planner on the
// whole floor's grid uses it).
// The grids are compared on a lattice of `sampleM` over grid A (the freespace's resolution is
// enough: finer sampling finds the same pieces); pieces smaller than `minAreaM2` are ignored, since
// the robot could not turn there. A piece's transfer point is its sample nearest its centroid.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/nav/planning/RegionGrid.h"

namespace rgnav {

// Transfer points in the map frame; `frameA`, `frameB`: the regions' frames in the map frame.
std::vector<Eigen::Vector2d> overlapTransfers(const RegionGrid& a, const Pose2D& frameA, const RegionGrid& b,
                                              const Pose2D& frameB, double sampleM, double minAreaM2);

}  // namespace rgnav
