// DiffDriveRobot: acceleration-limited velocity update, exact arc integration and the swept
// collision check of one step.
#include "core/sim/motion/DiffDriveRobot.h"

#include <algorithm>

#include "core/common/Errors.h"
#include "core/common/ValueChecks.h"

namespace rgnav {

namespace {

// sin(x)/x, exact near 0.
double sinc(double x) { return std::abs(x) < 1e-6 ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

// The pose after driving at constant (v, w) for t seconds: the chord of the arc, of length
// v*t*sinc(w*t/2), points along the mean heading (exact for any w, including 0).
Pose2D arc(const Pose2D& p, double v, double w, double t) {
  const double turn = w * t;
  const double chord = v * t * sinc(turn / 2.0);
  const double heading = p.theta + turn / 2.0;
  return {p.x + chord * std::cos(heading), p.y + chord * std::sin(heading),
          normalizeAngle(p.theta + turn)};
}

double approach(double current, double target, double maxChange) {
  return current + std::clamp(target - current, -maxChange, maxChange);
}

}  // namespace

void validate(const DiffDriveConfig& config) {
  validate(config.footprint);
  requirePositive(config.maxTranslationalVelocity, "maximum translational velocity");
  requirePositive(config.maxRotationalVelocity, "maximum rotational velocity");
  requirePositive(config.maxTranslationalAcceleration, "maximum translational acceleration");
  requirePositive(config.maxRotationalAcceleration, "maximum rotational acceleration");
}

DiffDriveRobot::DiffDriveRobot(const DiffDriveConfig& config, const Pose2D& start)
    : config_(config), pose_(start) {
  validate(config_);
}

void DiffDriveRobot::command(const VelocityCommand& target) {
  requireFiniteArgument(target.translational, "DiffDriveRobot: translational velocity");
  requireFiniteArgument(target.rotational, "DiffDriveRobot: rotational velocity");
  target_.translational = std::clamp(target.translational, -config_.maxTranslationalVelocity,
                                     config_.maxTranslationalVelocity);
  target_.rotational = std::clamp(target.rotational, -config_.maxRotationalVelocity,
                                  config_.maxRotationalVelocity);
}

bool DiffDriveRobot::collidesAt(const Pose2D& pose, const OccupancyGrid& grid,
                                std::span<const DiskObstacle> obstacles) const {
  if (config_.footprint.overlapsGrid(grid, pose)) return true;
  return std::any_of(obstacles.begin(), obstacles.end(), [&](const DiskObstacle& o) {
    return config_.footprint.overlapsDisk(pose, o.centre, o.radius);
  });
}

StepOutcome DiffDriveRobot::step(double dt, const OccupancyGrid& grid, std::span<const DiskObstacle> obstacles) {
  if (!(std::isfinite(dt) && dt > 0.0)) {
    throw InvalidArgumentError("DiffDriveRobot: time step must be positive and finite");
  }
  velocity_.translational = approach(velocity_.translational, target_.translational,
                                     config_.maxTranslationalAcceleration * dt);
  velocity_.rotational = approach(velocity_.rotational, target_.rotational,
                                  config_.maxRotationalAcceleration * dt);
  const double v = velocity_.translational;
  const double w = velocity_.rotational;
  const double spacing = grid.resolution() / 4.0;
  // The farthest any footprint point travels: the centre's arc plus the turn at the circumradius
  // (a disk around the rotation centre sweeps nothing by turning).
  const double turnReach = config_.footprint.shape == Footprint::Shape::Disk ? 0.0 : config_.footprint.circumradius();
  const double travel = (std::abs(v) + std::abs(w) * turnReach) * dt;
  const int samples = std::max(1, static_cast<int>(std::ceil(travel / spacing)));
  const Pose2D start = pose_;
  Pose2D lastFree = start;
  for (int k = 0; k <= samples; ++k) {
    const Pose2D p = k == 0 ? start : arc(start, v, w, dt * k / samples);
    if (collidesAt(p, grid, obstacles)) {
      pose_ = lastFree;
      velocity_ = {};
      target_ = {};
      return StepOutcome::Collided;
    }
    lastFree = p;
  }
  pose_ = lastFree;
  return StepOutcome::Moved;
}

}  // namespace rgnav
