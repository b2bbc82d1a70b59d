// detectObjects: the 2D objects of a toured map from its scans (true poses), with the project's
// line and object libraries; the world's occupancy is never looked at (the grid only gives the
// cell geometry for free-space bookkeeping).
//   1. Per ground-truth room one RegionLineMap (thesis 5.2, merging with the 3.1.1 parameters)
//      fed with the scans taken in that room; RectangleDetector on each map (3.2: restrictive
//      grouping, alpha 80-100 degrees, DN_max = DO_min = 200 mm).
//   2. Rectangles whose inside the laser saw through (rooms, corridors) are dropped; duplicates
//      from neighbouring rooms are suppressed (IoU > 0.5, more confident first).
//   3. All scan points of the tour (thinned, PointCloud) that do not lie on a long map line
//      (walls, cabinet fronts) go to the CircleDetector (Table 2.1); circles seen through are
//      dropped, as are circles on a kept rectangle.
//   4. Small objects (table and chair legs, bins too small for a circle fit): the remaining
//      points are clustered (PointClustering, isolation gap); a cluster with a point on a long
//      line is part of a wall and dropped; the others are split at a finer gap into single
//      objects, each a detection if it has enough points and is small.
#pragma once

#include <cstddef>
#include <vector>

#include "core/objects/CircleDetector.h"
#include "core/objects/RectangleDetector.h"
#include "core/sim/OccupancyGrid.h"
#include "tests/eval/objects/Detection.h"
#include "tests/eval/objects/TourScans.h"

namespace rgnav {

struct ObjectDetectionParams {
  RectangleDetectorParams rectangles;  // thesis defaults
  CircleDetectorParams circles;        // library defaults
  double structureLengthM = 0.5;       // a map line at least this long is structure
  double structureDistanceM = 0.03;    // a point this close to a structure line lies on it
  double maxSeenFreeShare = 0.2;       // of a rectangle's or circle's cells, at most
  double onObjectMarginM = 0.05;       // a point this close to a kept rectangle/circle is part of it
  double isolationGapM = 0.10;         // clusters closer than this are one group
  double objectGapM = 0.04;            // within a group, clusters this far apart are separate objects
  std::size_t minClusterPoints = 3;
  double maxClusterExtentM = 0.5;      // bounding-box diagonal of a small object, at most
  std::size_t freeSpaceScanStride = 5; // every n-th scan marks seen-free cells
};

struct DetectionSummary {
  std::vector<Detection> detections;
  std::size_t scans = 0;
  std::size_t mapLines = 0;     // lines of all region line maps
  std::size_t cloudPoints = 0;  // after thinning
  std::vector<bool> hitCells;   // row-major: cells holding a pushed scan point (what the laser hit)
};

DetectionSummary detectObjects(const TourScans& tour, const OccupancyGrid& geometry,
                               const ObjectDetectionParams& params = {});

}  // namespace rgnav
