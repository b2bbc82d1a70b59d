// mainDirections: the dominant orientations of a region's 2D line segment map (thesis 2.1.1,
// table 2.1 "main axes/directions of the 2D line segments"). Orientations are undirected, in
// [0, pi). The lines' orientations go into a histogram weighted by line length, smoothed with a
// triangular kernel of half width windowRad. The first main direction is at the highest peak; the
// second at the highest point at least minSeparationRad away from the first. Each direction's angle
// is the length-weighted circular mean (on doubled angles) of the lines within +-windowRad of its
// peak, its length their total length. The second is reported if its length is at least
// minSecondWeight times the first's.
// Rectangular rooms give two directions about 90 degrees apart; a long hallway may give one.
#pragma once

#include <span>
#include <vector>

#include "core/lines/LineSegment.h"

namespace rgnav {

struct MainDirectionParams {
  double binWidthRad = M_PI / 180.0;         // histogram bin
  double windowRad = 5.0 * M_PI / 180.0;     // half width of the window a direction gathers
  double minSeparationRad = M_PI / 6.0;      // of the second direction from the first
  double minSecondWeight = 0.25;             // second direction's length relative to the first
};

template <class V>
void describe(V& v, MainDirectionParams& c) {
  v.degrees("bin_width_deg", c.binWidthRad);
  v.degrees("window_deg", c.windowRad);
  v.degrees("min_separation_deg", c.minSeparationRad);
  v.field("min_second_weight", c.minSecondWeight);
}

struct MainDirection {
  double angleRad = 0.0;  // in [0, pi)
  double lengthM = 0.0;   // total length of the lines within the window
  double share = 0.0;     // lengthM / total length of the map
};

// Zero (no line of positive length), one or two directions, the heavier first. Throws
// InvalidArgumentError unless 0 < binWidthRad <= windowRad < minSeparationRad / 2,
// minSeparationRad <= pi / 2 and minSecondWeight in [0, 1].
std::vector<MainDirection> mainDirections(std::span<const LineSegment> lines, const MainDirectionParams& params = {});

}  // namespace rgnav
