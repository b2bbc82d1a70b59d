// detectRegionObjects: the 2D objects O of a region (thesis 2.1, Region <M, O, P, G_ref>; table
// 2.1, "2D rectangle") from its 2D line segment map, in the region frame: rectangles (thesis 3.2,
// RectangleDetector) that the laser did not see through.
// Thesis 3.2 groups quadrangles in the restrictive case (alpha 80-100 degrees, DN_max = DO_min =
// 200 mm). Deliberate differences, as in the project's object evaluation (rgnav-eval-objects):
//   - one corner may stay open (openCornerRectangles): furniture stands against walls, the wall
//     behind a cabinet is cut into two lines by it, so its fourth corner never closes;
//   - a rectangle whose inside the region's freespace map holds as free (more than
//     maxSeenFreeShare of the 15 cm cells whose centres lie in it) is no object but floor bounded
//     by walls (a room, a corridor, a desk seen between its legs); one more than maxAspectRatio
//     times as long as wide, or narrower than minWidthM, is a wall (both faces of a 0.1-0.3 m
//     wall or partition close into a rectangle), and one wider than maxWidthM is a room or a
//     corridor whose inside this region did not see (its walls seen through a door);
//   - of rectangles overlapping by more than rectangles.maxOverlapRatio (intersection over union)
//     only the most confident stays, after the filters above (a room-sized rectangle must not
//     suppress the cabinet inside it).
// Circles and small objects (legs, bins) need the scan points, which a region does not keep; the
// object evaluation finds them (tests/eval/objects).
#pragma once

#include <vector>

#include "core/lines/LineSegment.h"
#include "core/objects/RectangleDetector.h"
#include "core/rgmap/describe/FreespaceBitmap.h"

namespace rgnav {

// The thesis rectangle parameters (3.2) with one open corner allowed (grouping case A). A
// cabinet seen on two sides covers half its perimeter: the fit scatters such views over
// 0.46-0.52, so the minimum confidence is 0.45.
RectangleDetectorParams openCornerRectangles();

struct RegionObjectParams {
  RectangleDetectorParams rectangles = openCornerRectangles();
  double maxSeenFreeShare = 0.2;
  double maxAspectRatio = 10.0;
  double minWidthM = 0.35, maxWidthM = 2.0;
};

template <class V>
void describe(V& v, RegionObjectParams& c) {
  v.section("rectangles", c.rectangles);
  v.field("max_seen_free_share", c.maxSeenFreeShare);
  v.field("max_aspect_ratio", c.maxAspectRatio);
  v.field("min_width_m", c.minWidthM);
  v.field("max_width_m", c.maxWidthM);
}

// Most confident first. Throws InvalidArgumentError for invalid parameters (and as
// RectangleDetector does for its own).
std::vector<Rectangle2D> detectRegionObjects(const std::vector<LineSegment>& lines, const FreespaceBitmap& freespace,
                                             const RegionObjectParams& params = {});

}  // namespace rgnav
