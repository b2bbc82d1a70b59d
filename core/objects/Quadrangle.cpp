// Quadrangle hypotheses; see Quadrangle.h.
#include "core/objects/Quadrangle.h"

#include <algorithm>

#include "core/common/Errors.h"
#include "core/objects/SegmentRelations.h"

namespace rgnav {

SideCycle canonicalCycle(const SideCycle& cycle) {
  const std::size_t s = std::size_t(std::min_element(cycle.begin(), cycle.end()) - cycle.begin());
  const std::size_t next = cycle[(s + 1) % 4], previous = cycle[(s + 3) % 4];
  SideCycle out;
  for (std::size_t m = 0; m < 4; ++m) out[m] = next < previous ? cycle[(s + m) % 4] : cycle[(s + 4 - m) % 4];
  return out;
}

Quadrangle makeQuadrangle(const std::vector<LineSegment>& lines, const SideCycle& cycle) {
  Quadrangle q;
  q.sides = canonicalCycle(cycle);
  for (std::size_t m = 0; m < 4; ++m) {
    const auto corner = lineIntersection(lines.at(q.sides[m]), lines.at(q.sides[(m + 1) % 4]));
    if (!corner) throw InvalidArgumentError("quadrangle with parallel neighbouring sides");
    q.corners[m] = *corner;
  }
  return q;
}

Polygon outline(const Quadrangle& quadrangle) {
  return convexHull({quadrangle.corners.begin(), quadrangle.corners.end()});
}

}  // namespace rgnav
