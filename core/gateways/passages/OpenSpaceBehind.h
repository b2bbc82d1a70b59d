// seeThrough: the "open space behind the passage" test of thesis 4.2.1 (figure 4.11: valid and
// invalid hypotheses with respect to open space behind the gateway line). The thesis asks
// whether "there are hidden frontiers or visible openings of reasonable size behind the narrow
// passage"; we answer it with the beams between the two gateway points: a beam sees through if
// it got no return within the maximum range, or its point lies at least `depthM` beyond the
// gateway line (on the side away from the scanner). Beams that still hit the surfaces the
// gateway points lie on are not looked at: behind the line there is the same wall, not open
// space. Our reading, not the thesis' wording: it rejects niches, cabinets and recesses whose
// back is close behind the line.
#pragma once

#include <Eigen/Core>
#include <cstddef>

#include "core/common/SensorData.h"
#include "core/lines/ScanPoints.h"

namespace rgnav {

struct SeeThrough {
  std::size_t beams = 0;   // beams between the gateway points' surfaces (invalid ones not counted)
  std::size_t beyond = 0;  // of these, the ones that see through
};

// `a` and `b` are scan points of `scan` in the sensor frame (scanner at the origin), a.beam < b.beam;
// the beams looked at are those strictly between `firstBeam` and `lastBeam`, the ends of the
// surfaces of a and b towards each other (a.beam <= firstBeam, lastBeam <= b.beam).
SeeThrough seeThrough(const LaserScan& scan, const ScanPoint& a, const ScanPoint& b, std::size_t firstBeam,
                      std::size_t lastBeam, double depthM);

}  // namespace rgnav
