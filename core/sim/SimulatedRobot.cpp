// The simulator behind the servers (see SimulatedRobot.h).
#include "core/sim/SimulatedRobot.h"

#include <cmath>

#include "core/common/OdometryInterpolation.h"

namespace rgnav {

SimulatedRobot::SimulatedRobot(LoadedWorld world, const SimulationConfig& config, const Pose2D& start,
                               std::optional<Tour> tour, std::ostream* record, const SimulatedRobotOptions& options)
    : world_(std::move(world)),
      simulation_(world_.grid, config, start),
      options_(options),
      scans_(options.bufferCapacity),
      odometry_(options.bufferCapacity) {
  if (tour) tour_.emplace(std::move(*tour), PurePursuitConfig{});
  if (record) recorder_.emplace(*record);
}

void SimulatedRobot::stepLocked() {
  if (tour_) {
    if (tour_->finished()) return;
    simulation_.command(tour_->command(simulation_.truePose(), simulation_.time()));
  } else {
    const bool lapsed = simulation_.time() - commandedAt_ > options_.commandTimeoutSeconds;
    simulation_.command(lapsed ? VelocityCommand{} : commanded_);
  }
  const SimulationStep step = simulation_.step();
  if (step.collided && !colliding_ && options_.collisionLog) logCollision(step);
  colliding_ = step.collided;
  odometry_.push(step.odometry);
  if (recorder_) recorder_->write(step.odometry);
  if (step.scan) {
    scans_.push(*step.scan);
    if (recorder_) recorder_->write(*step.scan);
  }
  if (tour_ && tour_->finished()) {
    scans_.markEndOfData();
    odometry_.markEndOfData();
  }
}

void SimulatedRobot::logCollision(const SimulationStep& step) const {
  const Pose2D& p = step.truePose;
  *options_.collisionLog << "collision at t=" << step.odometry.stamp << " s: robot at (" << p.x << ", " << p.y << ", "
                         << p.theta << ") v=" << step.odometry.translationalVelocity << " m/s w=" << step.odometry.rotationalVelocity
                         << " rad/s";
  // The nearest person, in the robot's frame, with its velocity: whether it was a person and how
  // the two met.
  const Person* nearest = nullptr;
  double best = 0.0;
  for (const Person& person : simulation_.people()) {
    const double d = std::hypot(person.position.x - p.x, person.position.y - p.y);
    if (!nearest || d < best) {
      nearest = &person;
      best = d;
    }
  }
  if (nearest) {
    const double c = std::cos(p.theta), s = std::sin(p.theta);
    const double dx = nearest->position.x - p.x, dy = nearest->position.y - p.y;
    const WorldPoint& u = nearest->velocity;
    *options_.collisionLog << ", nearest person at (" << c * dx + s * dy << ", " << -s * dx + c * dy
                           << ") in the robot's frame walking (" << c * u.x + s * u.y << ", " << -s * u.x + c * u.y << ") m/s";
  }
  *options_.collisionLog << std::endl;
}

void SimulatedRobot::step() {
  std::lock_guard lock(mutex_);
  stepLocked();
}

void SimulatedRobot::advanceToNextScan() {
  if (options_.clock != SimClock::LockStep) return;
  const DataId next = scans_.latestId() + 1;
  while (scans_.latestId() < next && !scans_.endOfData()) stepLocked();
}

DataBatch<LaserScan> SimulatedRobot::scansSince(DataId afterId, std::size_t maxCount, const std::string&) {
  std::lock_guard lock(mutex_);
  // A consumer that has every scan pulls the next one; asking from beyond the latest scan pulls
  // no more than that (one call never runs a whole tour, whatever afterId a caller sends).
  if (afterId >= scans_.latestId()) advanceToNextScan();
  return scans_.since(afterId, maxCount);
}

DataBatch<OdometryReading> SimulatedRobot::odometrySince(DataId afterId, std::size_t maxCount, const std::string&) {
  std::lock_guard lock(mutex_);
  return odometry_.since(afterId, maxCount);
}

LaserScan SimulatedRobot::scan(DataId id) {
  std::lock_guard lock(mutex_);
  return scans_.get(id);
}

OdometryReading SimulatedRobot::odometryAt(Timestamp stamp) {
  std::lock_guard lock(mutex_);
  return interpolateOdometry(odometry_.records(), stamp);
}

DataId SimulatedRobot::latestScanId() {
  std::lock_guard lock(mutex_);
  return scans_.latestId();
}

DataId SimulatedRobot::oldestScanId() {
  std::lock_guard lock(mutex_);
  return scans_.oldestId();
}

DataId SimulatedRobot::latestOdometryId() {
  std::lock_guard lock(mutex_);
  return odometry_.latestId();
}

void SimulatedRobot::setVelocity(double translational, double rotational) {
  if (!std::isfinite(translational) || !std::isfinite(rotational))
    throw InvalidArgumentError("velocity command must be finite");
  std::lock_guard lock(mutex_);
  if (tour_) throw NotSupportedError("the simulator drives a room tour; start it without --tour to command it");
  commanded_ = {translational, rotational};
  commandedAt_ = simulation_.time();
}

Pose2D SimulatedRobot::truePoseOfScan(DataId id) {
  std::lock_guard lock(mutex_);
  if (id == 0) throw InvalidArgumentError("ID 0 names no scan; IDs start at 1");
  return simulation_.truePoseOfScan(id);
}

int SimulatedRobot::roomAt(WorldPoint p) const { return world_.truth ? world_.truth->roomAt(p) : -1; }

unsigned SimulatedRobot::roomCount() const { return world_.truth ? static_cast<unsigned>(world_.truth->roomCount) : 0; }

std::vector<DoorLine> SimulatedRobot::doorLines() const { return world_.truth ? world_.truth->doors : std::vector<DoorLine>{}; }

bool SimulatedRobot::tourFinished() {
  std::lock_guard lock(mutex_);
  return tour_ && tour_->finished();
}

std::uint64_t SimulatedRobot::robotCollisions() {
  std::lock_guard lock(mutex_);
  return simulation_.robotCollisions();
}

std::uint64_t SimulatedRobot::personBumps() {
  std::lock_guard lock(mutex_);
  return simulation_.personBumps();
}

std::vector<Person> SimulatedRobot::people() {
  std::lock_guard lock(mutex_);
  const std::span<const Person> people = simulation_.people();
  return {people.begin(), people.end()};
}

double SimulatedRobot::simulatedSeconds() {
  std::lock_guard lock(mutex_);
  return simulation_.time();
}

}  // namespace rgnav
