// Stepping the simulated robot, odometry and laser (see Simulation.h).
#include "core/sim/Simulation.h"

#include <cmath>
#include <string>

#include "core/common/Errors.h"
#include "core/sim/people/ContactBlame.h"

namespace rgnav {

namespace {
// Distinct, fixed streams for the parts that draw random numbers, so adding a draw to one part
// never changes what another produces.
constexpr std::uint64_t kOdometryStream = 0x9e3779b97f4a7c15ULL;
constexpr std::uint64_t kLaserStream = 0xbf58476d1ce4e5b9ULL;
constexpr std::uint64_t kPeopleStream = 0x94d049bb133111ebULL;

}  // namespace

void validate(const SimulationConfig& config) {
  if (!(config.stepSeconds > 0.0)) throw ConfigError("simulation: step_s must be positive");
  if (config.stepsPerScan < 1) throw ConfigError("simulation: steps_per_scan must be at least 1");
  validate(config.robot);
  validate(config.odometry);
  validate(config.people);
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
  if (config_.people.count > 0)
    crowd_.emplace(world_, config_.people, config_.people.seed.value_or(config_.seed ^ kPeopleStream),
                   config_.robot.footprint, start);
}

std::span<const Person> Simulation::people() const {
  if (!crowd_) return {};
  return crowd_->people();
}

std::span<const DiskObstacle> Simulation::peopleObstacles() const {
  if (!crowd_) return {};
  return crowd_->obstacles();
}

SimulationStep Simulation::step() {
  const Pose2D before = robot_.pose();
  const bool drove = robot_.step(config_.stepSeconds, world_, peopleObstacles()) == StepOutcome::Collided;
  // People walk on with the robot at its new pose; whoever would touch it stops short.
  // Each person who came into contact: the robot drove into it if its outline moved towards it
  // (ContactBlame.h), else the person walked into the robot (a bump).
  int droveIntoPeople = 0, walkedInto = 0;
  if (crowd_)
    for (const WorldPoint& person : crowd_->step(config_.stepSeconds, config_.robot.footprint, robot_.pose()))
      ++(robotDroveInto(config_.robot.footprint, robot_.pose(), robot_.velocity().translational,
                        robot_.velocity().rotational, person)
             ? droveIntoPeople
             : walkedInto);
  // One collision per step however many things the robot met.
  const bool collided = drove || droveIntoPeople > 0;
  robotCollisions_ += collided;
  personBumps_ += static_cast<std::uint64_t>(walkedInto);
  odometryPose_ = odometryNoise_.advance(odometryPose_, before, robot_.pose());
  time_ += config_.stepSeconds;
  ++steps_;

  SimulationStep out;
  out.truePose = robot_.pose();
  out.collided = collided;
  out.bumped = walkedInto > 0;
  out.odometry = OdometryReading{nextOdometryId_++, time_, odometryPose_, robot_.velocity().translational,
                                 robot_.velocity().rotational};
  if (steps_ % static_cast<std::uint64_t>(config_.stepsPerScan) == 0) {
    const DataId id = scanTruePoses_.size() + 1;
    out.scan = laser_.simulate(robot_.pose(), odometryPose_, id, time_, raycaster_, laserRng_, peopleObstacles());
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
