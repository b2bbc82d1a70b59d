// DiffDriveRobot: the simulated robot base. A differential (or synchro) drive whose state is the
// true pose and the current velocities; velocity commands are clamped to the maximum
// velocities and reached under acceleration limits; each step integrates the motion exactly
// along a circular arc (Thrun, Burgard, Fox, Probabilistic Robotics, 2005, section 5.3.3,
// velocity motion model, noise-free) and stops the robot at the last collision-free pose when
// its footprint (a disk or a rectangle: core/nav/grid/Footprint.h) would overlap a blocked cell
// or a round obstacle (a person).
#pragma once

#include <cmath>
#include <span>

#include "core/common/Pose2D.h"
#include "core/common/VelocityCommand.h"
#include "core/nav/grid/Footprint.h"
#include "core/raster/OccupancyGrid.h"
#include "core/sim/world/DiskObstacle.h"

namespace rgnav {

struct DiffDriveConfig {
  Footprint footprint = Footprint::disk(0.25);  // what must stay clear of walls and people
  double maxTranslationalVelocity = 1.0;        // m/s
  double maxRotationalVelocity = M_PI / 2.0;    // rad/s
  double maxTranslationalAcceleration = 0.5;    // m/s^2
  double maxRotationalAcceleration = M_PI / 2;  // rad/s^2
};

// Throws ConfigError naming the first value that is not positive and finite (footprint sizes too).
void validate(const DiffDriveConfig& config);

enum class StepOutcome { Moved, Collided };

class DiffDriveRobot {
 public:
  // Throws ConfigError for a bad configuration.
  DiffDriveRobot(const DiffDriveConfig& config, const Pose2D& start);

  // Sets the target velocities, clamped to the maximum velocities. Throws InvalidArgumentError
  // for non-finite values.
  void command(const VelocityCommand& target);

  // Advances by `dt` seconds: the velocities move towards the target by at most
  // acceleration * dt and are then held for the whole step (exact arc). On a collision with a
  // blocked cell or one of `obstacles` the robot stays at the last free pose along the arc
  // (checked whenever a point of the footprint may have moved a quarter cell), its velocities
  // and target drop to zero and Collided is returned (a robot placed overlapping an obstacle
  // does not move). Throws InvalidArgumentError for a non-positive or non-finite dt.
  StepOutcome step(double dt, const OccupancyGrid& grid, std::span<const DiskObstacle> obstacles = {});
  // Whether the footprint at `pose` overlaps a blocked cell or one of `obstacles`.
  bool collidesAt(const Pose2D& pose, const OccupancyGrid& grid, std::span<const DiskObstacle> obstacles = {}) const;

  const Pose2D& pose() const { return pose_; }
  const VelocityCommand& velocity() const { return velocity_; }
  const DiffDriveConfig& config() const { return config_; }

 private:
  DiffDriveConfig config_;
  Pose2D pose_;
  VelocityCommand velocity_;
  VelocityCommand target_;
};

}  // namespace rgnav
