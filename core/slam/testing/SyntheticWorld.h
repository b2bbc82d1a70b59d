// Test helper: planar worlds made of wall segments and an ideal laser that ray-casts them, to
// produce scans with exactly known poses (a box-shaped room with furniture, a corridor with door
// recesses, a loop around a block).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/common/SensorData.h"

namespace rgnav::testing {

struct Wall {
  Eigen::Vector2d a;
  Eigen::Vector2d b;
};
using World = std::vector<Wall>;

// A 10 m x 8 m room with two boxes and a pillar (no symmetry), origin at its centre.
World boxWorld();
// A 30 m long, 2 m wide corridor along x with door recesses every few metres, origin at its centre.
World corridorWorld();
// A rectangular ring corridor around a 16 m x 10 m block: a loop of about 60 m, origin at the
// block's centre; the corridor's centre line runs at x = +-9.5, y = +-6.5.
World loopWorld();

// Poses along the centre line of loopWorld()'s ring corridor, counter-clockwise from (9.5, -6.5),
// `step` metres apart, turning on the spot at the corners; `laps` times around.
std::vector<Pose2D> loopTrajectory(double step, int laps);

// Odometry that drifts from `truth`: every increment scaled by (1 + scaleError) and turned by
// headingErrorPerMetre times its length. Starts at truth[0].
std::vector<Pose2D> driftingOdometry(const std::vector<Pose2D>& truth, double scaleError, double headingErrorPerMetre);

struct SyntheticRun {
  std::vector<Pose2D> truth;
  std::vector<LaserScan> scans;  // IDs 1, 2, ...; odometry drifting, sensorPose the truth
};
// Two laps of loopWorld() at 0.1 m steps, odometry 2 % long and turning 1.5 degrees per metre.
SyntheticRun ringRun();

// A 180-degree, 1-degree scan (FLASER geometry) taken at `pose`; beams hitting nothing within
// maxRange are +infinity.
LaserScan simulateScan(const World& world, const Pose2D& pose, DataId id = 1, double maxRange = 30.0);

}  // namespace rgnav::testing
