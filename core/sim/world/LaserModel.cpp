// LaserModel: configuration checks, true ranges from the raycaster and the round obstacles, noise
// and dropouts.
#include "core/sim/world/LaserModel.h"

#include "core/common/Errors.h"
#include "core/sim/world/DiskRaycast.h"

namespace rgnav {
namespace {

std::size_t countBeams(const LaserConfig& c) {
  if (!(c.fieldOfView > 0.0 && c.fieldOfView <= 2.0 * M_PI)) {
    throw InvalidArgumentError("LaserModel: field of view must lie in (0, 2 pi]");
  }
  if (!(c.angularResolution > 0.0)) throw InvalidArgumentError("LaserModel: angular resolution must be positive");
  const double steps = c.fieldOfView / c.angularResolution;
  if (std::abs(steps - std::round(steps)) > 1e-6) {
    throw InvalidArgumentError("LaserModel: the field of view must be a whole number of angular steps");
  }
  if (!(c.maxRange > 0.0)) throw InvalidArgumentError("LaserModel: max range must be positive");
  if (!(c.mountingHeight > 0.0)) throw InvalidArgumentError("LaserModel: mounting height must be positive");
  if (!std::isfinite(c.forwardOffset)) throw InvalidArgumentError("LaserModel: forward offset must be finite");
  if (!(c.rangeNoiseSigma >= 0.0)) throw InvalidArgumentError("LaserModel: range noise sigma must not be negative");
  if (!(c.dropoutProbability >= 0.0 && c.dropoutProbability <= 1.0)) {
    throw InvalidArgumentError("LaserModel: dropout probability must lie in [0, 1]");
  }
  return static_cast<std::size_t>(std::round(steps)) + 1;
}

}  // namespace

LaserModel::LaserModel(const LaserConfig& config) : config_(config), beamCount_(countBeams(config)) {}

Pose2D LaserModel::laserPose(const Pose2D& robotPose) const {
  return compose(robotPose, {config_.forwardOffset, 0.0, 0.0});
}

LaserScan LaserModel::simulate(const Pose2D& robotTruePose, const Pose2D& odometryPose, DataId id, Timestamp stamp,
                               const Raycaster& raycaster, std::mt19937_64& rng,
                               std::span<const DiskObstacle> obstacles) const {
  LaserScan scan;
  scan.id = id;
  scan.stamp = stamp;
  scan.odometry = odometryPose;
  scan.sensorPose = laserPose(robotTruePose);
  scan.startAngle = startAngle();
  scan.angleIncrement = config_.angularResolution;
  scan.maxRange = config_.maxRange;
  scan.ranges.resize(beamCount_);
  raycaster.scan(scan.sensorPose, scan.startAngle, scan.angleIncrement, scan.maxRange, scan.ranges);
  for (const DiskObstacle& obstacle : obstacles) {
    for (std::size_t i = 0; i < beamCount_; ++i) {
      const double angle = scan.sensorPose.theta + scan.startAngle + static_cast<double>(i) * scan.angleIncrement;
      const double hit = castToDisk({scan.sensorPose.x, scan.sensorPose.y}, angle, obstacle);
      if (hit <= scan.maxRange && hit < scan.ranges[i]) scan.ranges[i] = static_cast<float>(hit);
    }
  }

  std::normal_distribution<double> noise(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (float& range : scan.ranges) {
    const double error = config_.rangeNoiseSigma * noise(rng);
    const bool dropout = uniform(rng) < config_.dropoutProbability;
    if (dropout || std::isinf(range)) {
      range = LaserScan::kNoReturn;
      continue;
    }
    const double measured = std::max(0.0, range + error);
    range = measured < config_.maxRange ? static_cast<float>(measured) : LaserScan::kNoReturn;
  }
  return scan;
}

}  // namespace rgnav
