// Stepping the simulated robot, odometry and laser (see Simulation.h).
#include "core/sim/Simulation.h"

#include <string>

#include "core/common/Errors.h"

namespace rgnav {

namespace {
// Distinct, fixed streams for the parts that draw random numbers, so adding a draw to one part
// never changes what another produces.
constexpr std::uint64_t kOdometryStream = 0x9e3779b97f4a7c15ULL;
constexpr std::uint64_t kLaserStream = 0xbf58476d1ce4e5b9ULL;

}  // namespace

void validate(const SimulationConfig& config) {
  if (!(config.stepSeconds > 0.0)) throw ConfigError("simulation: step_s must be positive");
  if (config.stepsPerScan < 1) throw ConfigError("simulation: steps_per_scan must be at least 1");
  validate(config.robot);
  validate(config.odometry);
}

Simulation::Simulation(const OccupancyGrid& world, const SimulationConfig& config, const Pose2D& start, Timestamp startTime)
    : world_(world),
      config_((validate(config), config)),
      raycaster_(world),
      laser_(config.laser),
      robot_(config.robot, start),
      odometryNoise_(config.odometry, config.seed ^ kOdometryStream),
      laserRng_(config.seed ^ kLaserStream),
      odometryPose_(start),
      time_(startTime) {
  if (robot_.collidesAt(start, world_))
    throw InvalidArgumentError("simulation: the start pose (" + std::to_string(start.x) + ", " +
                               std::to_string(start.y) + ") is not free for the robot");
}

SimulationStep Simulation::step() {
  const Pose2D before = robot_.pose();
  const bool collided = robot_.step(config_.stepSeconds, world_) == StepOutcome::Collided;
  collisions_ += collided;
  odometryPose_ = odometryNoise_.advance(odometryPose_, before, robot_.pose());
  time_ += config_.stepSeconds;
  ++steps_;

  SimulationStep out;
  out.truePose = robot_.pose();
  out.collided = collided;
  out.odometry = OdometryReading{nextOdometryId_++, time_, odometryPose_, robot_.velocity().translational,
                                 robot_.velocity().rotational};
  if (steps_ % static_cast<std::uint64_t>(config_.stepsPerScan) == 0) {
    const DataId id = scanTruePoses_.size() + 1;
    out.scan = laser_.simulate(robot_.pose(), odometryPose_, id, time_, raycaster_, laserRng_);
    scanTruePoses_.push_back(robot_.pose());
  }
  return out;
}

Pose2D Simulation::truePoseOfScan(DataId id) const {
  if (id == 0 || id > scanTruePoses_.size())
    throw NotAvailableError("no scan " + std::to_string(id) + " (scans so far: " +
                            std::to_string(scanTruePoses_.size()) + ")");
  return scanTruePoses_[id - 1];
}

}  // namespace rgnav
