// SimulatedRobot: the simulator as the Laser, Base and GroundTruth servers see it: a Simulation
// driven either by velocity commands (which lapse after commandTimeout of simulated time, so a
// vanished client cannot leave the robot driving) or by a room tour, its scans and odometry in
// bounded ID buffers, optionally recorded as a CARMEN log. Two clocks: real time (a caller
// steps it every step_s of wall time) and lock-step (it advances only when a laser consumer asks
// for a scan it does not have yet: as fast as the consumers allow, and deterministic for a seed).
// Thread-safe.
#pragma once

#include <mutex>
#include <optional>
#include <ostream>

#include "core/common/DataBuffer.h"
#include "core/common/SensorStreams.h"
#include "core/sim/LoadedWorld.h"
#include "core/sim/Simulation.h"
#include "core/sim/TourDriver.h"
#include "core/sim/motion/CarmenLogWriter.h"

namespace rgnav {

enum class SimClock { RealTime, LockStep };

struct SimulatedRobotOptions {
  SimClock clock = SimClock::RealTime;
  std::size_t bufferCapacity = 20000;
  double commandTimeoutSeconds = 0.5;  // simulated seconds a velocity command holds
  std::ostream* collisionLog = nullptr;  // a line per collision (its first step), if set
};

class SimulatedRobot : public LaserStream, public BaseStream {
 public:
  // `tour`: drive it (velocity commands are refused); without one, velocity commands drive.
  // `record`: where to write the CARMEN log (may be null); must outlive the robot.
  SimulatedRobot(LoadedWorld world, const SimulationConfig& config, const Pose2D& start, std::optional<Tour> tour,
                 std::ostream* record, const SimulatedRobotOptions& options);

  // One simulation step (the real-time clock's tick); nothing once a tour has ended.
  void step();

  // Lock-step: a caller that has every scan (afterId >= the latest) makes the simulation step
  // until the next scan exists (any consumer paces it); one call advances one scan at most.
  DataBatch<LaserScan> scansSince(DataId afterId, std::size_t maxCount, const std::string& consumer) override;
  LaserScan scan(DataId id) override;
  DataId latestScanId() override;
  DataId oldestScanId() override;
  DataBatch<OdometryReading> odometrySince(DataId afterId, std::size_t maxCount, const std::string& consumer) override;
  OdometryReading odometryAt(Timestamp stamp) override;
  DataId latestOdometryId() override;
  // NotSupportedError while a tour drives; InvalidArgumentError for non-finite values.
  void setVelocity(double translational, double rotational) override;

  Pose2D truePoseOfScan(DataId id);
  int roomAt(WorldPoint p) const;
  unsigned roomCount() const;
  std::vector<DoorLine> doorLines() const;

  bool tourFinished();
  // Simulation::robotCollisions and personBumps.
  std::uint64_t robotCollisions();
  std::uint64_t personBumps();
  // Where the people are now (empty without people).
  std::vector<Person> people();
  double simulatedSeconds();

 private:
  void stepLocked();
  void logCollision(const SimulationStep& step) const;
  void advanceToNextScan();  // lock-step

  mutable std::mutex mutex_;
  LoadedWorld world_;
  Simulation simulation_;
  std::optional<TourDriver> tour_;
  std::optional<CarmenLogWriter> recorder_;
  SimulatedRobotOptions options_;
  DataBuffer<LaserScan> scans_;
  DataBuffer<OdometryReading> odometry_;
  VelocityCommand commanded_;
  Timestamp commandedAt_ = 0.0;
  bool colliding_ = false;  // the last step collided
};

}  // namespace rgnav
