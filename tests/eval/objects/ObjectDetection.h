// detectObjects: the 2D objects of a toured map from its scans (true poses), with the project's
// line and object libraries; the world's occupancy is never looked at (the grid only gives the
// cell geometry for free-space bookkeeping).
//   1. Per ground-truth room one RegionLineMap (thesis 5.2, merging with the 3.1.1 parameters)
//      fed with the key scans taken in that room (the sensor moved 0.25 m or turned 15 degrees
//      since the last one: merging re-sorts the whole map per scan); RectangleDetector on each
//      map (3.2: alpha 80-100 degrees, DN_max = DO_min = 200 mm, but one open corner allowed,
//      see openCornerRectangles, RegionObjects.h).
//   2. Rectangles whose inside the laser saw through (BeamEvidence: rooms, corridors) are
//      dropped, as are those more than ten times as long as wide (walls: the most elongated
//      furniture of the ten maps is about 1:8); duplicates from neighbouring rooms are
//      suppressed (IoU > 0.5, more confident first).
//   3. All scan points of the tour (thinned, PointCloud) that do not lie on a structure line
//      (StructureLines: map lines >= 1 m made of >= 3 scan segments, and their continuation for
//      1 m: walls, cabinet fronts) go to the CircleDetector (Table 2.1); circles seen through are
//      dropped, as are flat ones (a line fits their points nearly as well: wall ends) and
//      circles on a kept rectangle.
//   4. Small objects (table and chair legs, bins too small for a circle fit): the remaining
//      points are clustered (PointClustering, isolation gap); a cluster with a point on a
//      structure line is part of a wall and dropped; the others are split at a finer gap into
//      single objects, each a detection if it has enough points and is small. Its footprint: the
//      cells of the hull of its pushed points (PointCloud) and of those points, less cells seen
//      free, grown by one cell into unobserved cells (its hidden back).
#pragma once

#include <cstddef>
#include <vector>

#include "core/objects/CircleDetector.h"
#include "core/objects/RectangleDetector.h"
#include "core/raster/OccupancyGrid.h"
#include "core/rgmap/describe/RegionObjects.h"
#include "tests/eval/objects/Detection.h"
#include "tests/eval/objects/TourScans.h"

namespace rgnav {

// The circle detector's defaults with a smaller clustering gap: the scan points of a whole tour
// lie dense on every surface, and chairs stand closer than 10 cm around round tables.
inline CircleDetectorParams tightCircles() {
  CircleDetectorParams params;
  params.clusterGapM = 0.05;
  return params;
}

struct ObjectDetectionParams {
  RectangleDetectorParams rectangles = openCornerRectangles();
  CircleDetectorParams circles = tightCircles();
  double structureLengthM = 1.0;       // a map line at least this long is structure ...
  std::size_t structureSupport = 3;    // ... if at least this many scan segments made it
  double structureDistanceM = 0.03;    // a point this close to a structure line lies on it
  double structureExtensionM = 1.0;    // ... or to its continuation this far beyond an end
  double maxSeenFreeShare = 0.2;       // of a rectangle's or circle's cells, at most
  double maxAspectRatio = 10.0;        // longer and thinner rectangles are walls
  double minLineToCircleResidual = 1.5;  // a circle's points: rms to their TLS line / rms to the circle
  double onObjectMarginM = 0.05;       // a point this close to a kept rectangle/circle is part of it
  double isolationGapM = 0.10;         // clusters closer than this are one group
  double objectGapM = 0.04;            // within a group, clusters this far apart are separate objects
  std::size_t minClusterPoints = 20;   // thinned points of a small object, at least
  int hiddenSteps = 1;                 // a small object's footprint grows this far into unobserved cells
  double maxClusterExtentM = 0.5;      // bounding-box diagonal of a small object, at most
  double keyScanDistanceM = 0.25;      // line maps take a scan after the sensor moved this far
  double keyScanAngleRad = 15.0 * M_PI / 180.0;  // ... or turned this much
};

struct DetectionSummary {
  std::vector<Detection> detections;
  std::size_t scans = 0;
  std::size_t keyScans = 0;     // added to line maps
  std::size_t mapLines = 0;     // lines of all region line maps, after merging
  std::vector<bool> hitCells;   // row-major: cells a laser return fell into
};

DetectionSummary detectObjects(const TourScans& tour, const OccupancyGrid& geometry,
                               const ObjectDetectionParams& params = {});

}  // namespace rgnav
