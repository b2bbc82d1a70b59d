// TrackingSuite: the fixed chains of the trajectory-tracking evaluation (issue 27, "rgctl eval
// tracking"): straights, arcs, clothoid turns, slaloms, a loop, a G1 clothoid join and a turn on
// the spot before a straight, each with
// the top speed it is driven at (0.3-1.0 m/s). Every chain starts at the origin heading east.
#pragma once

#include <string>
#include <vector>

#include "core/nav/motion/TrajectoryChain.h"

namespace rgnav {

struct TrackingCase {
  std::string name;
  TrajectoryChain chain;
  double maxVelocity;  // m/s
};

std::vector<TrackingCase> trackingSuite();

}  // namespace rgnav
