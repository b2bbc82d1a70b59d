// MeasurementHull: the convex hull of the obstacle measurements inside a region (the hits of
// RegionBeams.h), kept incrementally: after each scan it is the hull of its old vertices and the
// new points. The region's bounding rectangles (thesis 2.1.1: "2D bounding rectangle ... based on
// the metrical description"; 5.2: "a bounding rectangle for the scans belonging to that region,
// whereas only measurements inside the region are considered") enclose this hull: every
// rectangle that encloses the points encloses their hull. A rigid transform keeps a hull convex,
// so merging the hulls of two regions is exact.
#pragma once

#include <Eigen/Core>

#include "core/common/Pose2D.h"
#include "core/objects/ConvexPolygon.h"
#include "core/rgmap/describe/RegionBeams.h"

namespace rgnav {

class MeasurementHull {
 public:
  void addBeams(const RegionBeams& beams);
  // Adds the measurements of another region whose frame has the pose `otherInThis` here.
  void mergeFrom(const MeasurementHull& other, const Pose2D& otherInThis);

  // Counter-clockwise; fewer than three vertices while the points are fewer or collinear.
  const Polygon& vertices() const { return vertices_; }

 private:
  void extend(std::vector<Eigen::Vector2d> points);

  Polygon vertices_;
};

}  // namespace rgnav
