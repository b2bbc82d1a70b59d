// RectangleDetector: rectangular 2D objects from a 2D line segment map, thesis 3.2. The map is
// expected to be merged already (RegionLineMap merges with the thesis' restrictive 3.1.1
// parameters, 3 degrees / 20 mm / 150 mm, the preprocessing 3.2 asks for). Quadrangle
// hypotheses come from the two-stage grouping (3.1; the thesis uses the restrictive case with
// alpha 80-100 degrees, DN_max = DO_min = 200 mm for laser data). Each hypothesis becomes a
// rectangle: heading from the length-weighted mean direction (modulo 90 degrees) of its edges
// from corner to corner, each side placed at the mean offset of its two corners, centre and
// size from the opposite sides. Its confidence is the share of the rectangle's perimeter covered by the segments
// that form its sides.
// Partial views: in the restrictive case all four corners must be closed (each within DN_max);
// with grouping.restrictive = false one corner may stay open (e.g. two sides seen only in
// part), as the thesis allows for images. Two or three sides without a fourth line give no
// rectangle, as in the thesis. Deliberate differences: hypotheses below minConfidence are
// dropped, and of rectangles overlapping by more than maxOverlapRatio in intersection over union
// only the most confident stays. The thesis removes hypotheses contained in larger ones, which
// marks regions of interest (QuadrangleGrouping::group) but would drop a table inside its room.
#pragma once

#include <functional>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/objects/QuadrangleGrouping.h"

namespace rgnav {

struct Rectangle2D {
  Pose2D pose;           // centre; theta: direction of the length axis, in [0, pi)
  double lengthM = 0.0;  // >= widthM
  double widthM = 0.0;
  double confidence = 0.0;  // share of the perimeter seen, in [0, 1]
  SideCycle sides{};        // indices of the lines forming its sides, in cyclic order
};

struct RectangleDetectorParams {
  GroupingParams grouping;
  double minConfidence = 0.5;
  double maxOverlapRatio = 0.5;  // intersection over union, in [0, 1)
};

template <class V>
void describe(V& v, RectangleDetectorParams& c) {
  v.section("grouping", c.grouping);
  v.field("min_confidence", c.minConfidence);
  v.field("max_overlap_ratio", c.maxOverlapRatio);
}

// The rectangle fitted to a quadrangle hypothesis of `lines`.
Rectangle2D fitRectangle(const std::vector<LineSegment>& lines, const Quadrangle& quadrangle);

// Corners of the rectangle, counter-clockwise.
Polygon rectangleOutline(const Rectangle2D& rectangle);

class RectangleDetector {
 public:
  // Throws InvalidArgumentError for invalid parameters.
  explicit RectangleDetector(const RectangleDetectorParams& params = {});

  // Rectangles found in `lines`, most confident first; with `keep`, only those it accepts (tested
  // before overlaps are suppressed, so that a rejected rectangle suppresses none).
  std::vector<Rectangle2D> detect(const std::vector<LineSegment>& lines,
                                  const std::function<bool(const Rectangle2D&)>& keep = {}) const;

 private:
  RectangleDetectorParams params_;
  QuadrangleGrouping grouping_;
};

}  // namespace rgnav
