// Swept-footprint check of the Collision Avoidance (thesis 5.5.3: "if a collision is detected the
// respective trajectory segments are replanned"): whether the robot's Footprint (disk or
// rectangle), driven along a TrajectoryChain, keeps a safety margin from every obstacle cell, and
// its clearance along the way. Poses are sampled along the chain every few centimetres. Each pose
// first asks the Euclidean distance transform of the obstacle cells (cv::distanceTransform) for
// the distance at the rotation centre: if that minus the circumradius already exceeds what is
// asked, the pose is clear; only near obstacles is the exact footprint measured against each
// obstacle cell in a window (cells count as disks of half a cell's side: within 1 cm at 5 cm
// cells). Checking only the chain's end, as a naive check would, misses corners cut on the way.
#pragma once

#include <vector>

#include "core/nav/grid/Footprint.h"
#include "core/nav/motion/TrajectoryChain.h"
#include "core/raster/OccupancyGrid.h"

namespace rgnav {

class ObstacleClearance {
 public:
  // `obstacles`: Occupied cells are obstacles, everything else (and outside) is free.
  explicit ObstacleClearance(OccupancyGrid obstacles);

  const OccupancyGrid& obstacles() const { return obstacles_; }
  // Distance (m) from the point to the nearest obstacle cell (a lower bound, within 1.5 cells).
  double pointClearance(WorldPoint p) const;
  // Distance (m) from the footprint at `pose` to the nearest obstacle cell, negative on overlap:
  // measured exactly when below `exactBelow`, otherwise a lower bound of at least `exactBelow`.
  double footprintClearance(const Footprint& footprint, const Pose2D& pose, double exactBelow) const;

 private:
  double windowClearance(const Footprint& footprint, const Pose2D& pose, double reach) const;

  OccupancyGrid obstacles_;
  std::vector<float> distanceCells_;  // per cell, to the nearest obstacle cell's centre, cells
};

struct SweptCheck {
  bool clear = true;          // the whole chain keeps the margin
  double freeLength = 0.0;    // m along the chain before the first pose that does not
  double minClearance = 0.0;  // m, the smallest footprint clearance over the free part (capped)
};

struct SweptCheckOptions {
  double marginM = 0.05;      // required clearance
  double stepM = 0.03;        // sampling along the chain
  double clearanceCapM = 0.5; // clearances are measured exactly up to margin + this
  double reliefM = 0.3;       // a chain starting closer than the margin must keep its start's
                              // clearance over this length (then the margin)
};

SweptCheck checkSwept(const ObstacleClearance& clearance, const TrajectoryChain& chain, const Footprint& footprint,
                      const SweptCheckOptions& options);

}  // namespace rgnav
