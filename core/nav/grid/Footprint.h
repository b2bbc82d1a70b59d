// Footprint: the robot's outline seen from above, a disk around its rotation centre or a
// rectangle (length along its heading, width across) whose centre may sit ahead of the rotation
// centre. The simulator's collision check, the Collision Avoidance's swept-footprint check and
// the evaluations all use it. Overlap tests are exact (touching is not overlapping).
#pragma once

#include <vector>

#include "core/common/Pose2D.h"
#include "core/raster/OccupancyGrid.h"

namespace rgnav {

struct Footprint {
  enum class Shape { Disk, Rectangle };
  Shape shape = Shape::Disk;
  double radius = 0.25;        // m, Disk
  double length = 0.0;         // m, Rectangle, along the heading
  double width = 0.0;          // m, Rectangle, across
  double centerOffset = 0.0;   // m, Rectangle: its centre ahead of the rotation centre

  static Footprint disk(double radius);
  static Footprint rectangle(double length, double width, double centerOffset = 0.0);

  // The farthest any point of the footprint is from the rotation centre.
  double circumradius() const;
  // The largest disk around the rotation centre inside the footprint (0 if the centre is outside).
  double inscribedRadius() const;
  // The footprint's corners at `pose` (Rectangle; a Disk has none).
  std::vector<WorldPoint> corners(const Pose2D& pose) const;

  // Whether the footprint at `pose` overlaps the disk (centre, r).
  bool overlapsDisk(const Pose2D& pose, WorldPoint centre, double r) const;
  // The footprint's point (at `pose`) nearest to `p` (p itself when inside).
  WorldPoint nearestPoint(const Pose2D& pose, WorldPoint p) const;
  // Whether the footprint at `pose` overlaps a blocked cell (occupied, unknown or outside).
  bool overlapsGrid(const OccupancyGrid& grid, const Pose2D& pose) const;
};

// Throws ConfigError for non-positive or non-finite sizes.
void validate(const Footprint& footprint);

}  // namespace rgnav
