// Test helper: a server set for the LowLevelDrive module's integration and fault tests: the
// simulator in real time following velocity commands on the office floor (config/worlds/
// office.yaml), starting at the main hallway's west end facing east (kStart), with noiseless
// odometry (so the odometry frame stays the world frame and the ground truth shows how well the
// drive tracked), and the LowLevelDrive module on its Base. Or, as in the demo set, the simulator
// in lock-step on its room tour, which refuses velocity commands. Clients for the Base, the ground truth
// and the drive, and the chains the tests send.
#pragma once

#include <memory>

#include "clientlibs/base/BaseClient.h"
#include "clientlibs/groundtruth/GroundTruthClient.h"
#include "clientlibs/laser/LaserClient.h"
#include "clientlibs/lowleveldrive/LowLevelDriveClient.h"
#include "tests/integration/IntegrationHelpers.h"

namespace rgnav::testing {

// The robot's pose when a scan was taken, true and on the simulation's clock.
struct TrueState {
  DataId scan = 0;
  Timestamp stamp = 0.0;
  Pose2D pose;
};

enum class SimulatorDriving { Velocity, Tour };

class MotionSet {
 public:
  static constexpr Pose2D kStart{1.5, 7.0, 0.0};

  // `setYaml`: extra top-level YAML of the set (e.g. kFastBackoff).
  explicit MotionSet(const std::string& setYaml = "", SimulatorDriving driving = SimulatorDriving::Velocity);

  TestCluster& cluster() { return *cluster_; }
  LowLevelDriveClient& drive() { return *drive_; }
  LaserClient& laser() { return *laser_; }
  // The newest odometry reading of the Base.
  OdometryReading latestOdometry();
  // The true pose at the newest scan / at scan `id`.
  TrueState latestTruth();
  TrueState truthAt(DataId id);

 private:
  ScratchDir scratch_;
  std::unique_ptr<TestCluster> cluster_;
  std::unique_ptr<BaseClient> base_;
  std::unique_ptr<LaserClient> laser_;
  std::unique_ptr<GroundTruthClient> truth_;
  std::unique_ptr<LowLevelDriveClient> drive_;
};

// A chain from the robot's odometry pose `from` (standing): `straightM` straight ahead, then a
// clothoid over `easeM` into an arc of `curvature` (1/m, left positive) for `arcM`; the reference
// leaves 0.3 s (odometry clock) after the reading.
DriveChain straightThenArc(std::uint64_t id, const OdometryReading& from, double straightM, double easeM,
                           double curvature, double arcM);

}  // namespace rgnav::testing
