// RegionDescription: the features of one region (thesis 2.1.1 and table 2.1, "feature vector for
// recognition and classification: bounding rectangle, 2D freespace and its 1st/2nd order moments,
// main axes" and "characteristic measures: accuracy, completeness"), computed in the region's own
// frame from its RegionEvidence, its 2D line segment map (RegionLineMap) and its gateways. The RG
// Mapping Kernel (5.2) computes it whenever it needs the current region's preliminary description
// and again when it finalises the region. Each feature is defined in its own header:
//   - bounding rectangles: BoundingRectangles.h, of the measurements inside the region;
//   - freespace: FreespaceBitmap.h (the 1-bit map and its byte size), FreespaceMoments.h;
//   - main directions of the line map: MainDirections.h;
//   - accuracy: LineMapAccuracy.h, on the evidence's measurement sample;
//   - completeness: FreespaceCompleteness.h;
//   - the 2D objects O (thesis 2.1: a region is <M, O, P, G_ref>): RegionObjects.h.
// Cost: linear in the grid cells plus sample points x map lines plus the quadrangle grouping of
// the line map (about a millisecond for a room).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "core/lines/LineSegment.h"
#include "core/rgmap/describe/BoundingRectangles.h"
#include "core/rgmap/describe/FreespaceCompleteness.h"
#include "core/rgmap/describe/FreespaceMoments.h"
#include "core/rgmap/describe/LineMapAccuracy.h"
#include "core/rgmap/describe/MainDirections.h"
#include "core/rgmap/describe/RegionEvidence.h"
#include "core/rgmap/describe/RegionObjects.h"

namespace rgnav {

struct DescriptionParams {
  AccuracyParams accuracy;
  MainDirectionParams directions;
  RegionObjectParams objects;
};

template <class V>
void describe(V& v, DescriptionParams& c) {
  v.section("accuracy", c.accuracy);
  v.section("directions", c.directions);
  v.section("objects", c.objects);
}

struct RegionDescription {
  Eigen::AlignedBox2d boundingBox;                  // axis-aligned; isEmpty() without measurements
  std::optional<OrientedRectangle> minimumAreaBox;  // nullopt without measurements
  FreespaceBitmap freespace;                        // the 1-bit freespace map (thesis 5.2)
  FreespaceMoments moments;                         // area, centroid, covariance, main axes
  // The freespace centroid relative to the bounding box, (0, 0) at its lower left and (1, 1) at
  // its upper right corner (thesis 2.1.1: "center of gravity with respect to the bounding box");
  // 0.5 along an axis where the box has no extent, zero without box or freespace.
  Eigen::Vector2d centroidInBox = Eigen::Vector2d::Zero();
  std::vector<MainDirection> mainDirections;  // of the line map
  LineMapAccuracy accuracy;
  FreespaceCompleteness completeness;
  std::vector<Rectangle2D> objects;  // region frame, most confident first
  std::size_t scanCount = 0;  // scans in the evidence it was made from

  std::size_t freespaceBytes() const { return freespace.bytes.size(); }
};

// Throws InvalidArgumentError for invalid params or gateway ends (see the feature headers).
RegionDescription describeRegion(const RegionEvidence& evidence, std::span<const LineSegment> lines,
                                 std::span<const GatewaySegment> gateways, const DescriptionParams& params = {});

}  // namespace rgnav
