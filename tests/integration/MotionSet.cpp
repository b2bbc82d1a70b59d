// The simulator and the LowLevelDrive module as a set (see MotionSet.h).
#include "tests/integration/MotionSet.h"

#include <fstream>

#include "core/config/ShippedConfig.h"

namespace rgnav::testing {
namespace {

// The simulator's built-in parameters with the odometry and range noise switched off.
const char* const kNoiselessSimulation =
    "odometry: {alpha1: 0, alpha2: 0, alpha3: 0, alpha4: 0}\n"
    "laser: {range_noise_sigma_m: 0}\n";

std::string writtenFile(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

}  // namespace

MotionSet::MotionSet(const std::string& setYaml, SimulatorDriving driving) : scratch_("rgnav-motion-set") {
  const std::string simulation = writtenFile(scratch_.file("noiseless.yaml"), kNoiselessSimulation);
  const std::string start =
      std::to_string(kStart.x) + "," + std::to_string(kStart.y) + "," + std::to_string(kStart.theta);
  std::vector<std::string> simulator{TestCluster::program("rgnav-sim"), "--world",
                                     shippedConfigFile("worlds/office.yaml"), "--config", simulation, "--start", start};
  if (driving == SimulatorDriving::Tour) {
    simulator.insert(simulator.end(), {"--clock", "lockstep", "--tour"});
  } else {
    simulator.insert(simulator.end(), {"--clock", "realtime"});
  }
  cluster_ = std::make_unique<TestCluster>(
      std::vector<ClusterModule>{
          {"Simulator", simulator, {"Laser", "Base", "GroundTruth"}},
          {"LowLevelDrive",
           {TestCluster::program("rgnav-lowleveldrive"), "--config", TestCluster::moduleConfig("lowleveldrive")},
           {"LowLevelDrive"},
           {"Simulator"}}},
      setYaml);
  const ClientSettings settings = cluster_->clientSettings();
  base_ = std::make_unique<BaseClient>(settings);
  laser_ = std::make_unique<LaserClient>(settings);
  truth_ = std::make_unique<GroundTruthClient>(settings);
  drive_ = std::make_unique<LowLevelDriveClient>(settings);
}

OdometryReading MotionSet::latestOdometry() {
  const DataId latest = base_->latestOdometryId();
  const DataBatch<OdometryReading> batch = base_->odometrySince(std::max<DataId>(latest, 1) - 1, 1);
  if (batch.records.empty()) throw std::runtime_error("the Base has no odometry");
  return batch.records.back();
}

TrueState MotionSet::latestTruth() { return truthAt(laser_->latestId()); }

TrueState MotionSet::truthAt(DataId id) { return {id, laser_->scan(id).stamp, truth_->truePose(id)}; }

DriveChain straightThenArc(std::uint64_t id, const OdometryReading& from, double straightM, double easeM,
                           double curvature, double arcM) {
  const TrajectorySegment straight{from.pose, straightM, 0.0, 0.0};
  const TrajectorySegment ease{straight.end(), easeM, 0.0, curvature / easeM};
  const TrajectorySegment arc{ease.end(), arcM, curvature, 0.0};
  return DriveChain{id, TrajectoryChain({straight, ease, arc}), 0.0, from.stamp + 0.3, 0.0};
}

}  // namespace rgnav::testing
