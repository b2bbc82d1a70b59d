// VelocityCommand: the velocities a differential drive is told to reach; what a path follower
// (core/nav) produces and a robot base (the simulated one in core/sim/motion) executes.
#pragma once

namespace rgnav {

struct VelocityCommand {
  double translational = 0.0;  // m/s, forward positive
  double rotational = 0.0;     // rad/s, counter-clockwise positive
};

}  // namespace rgnav
