// The modules that make the robot go in the High-Level Planning tests (see NavigationSet.h).
#include "tests/integration/NavigationSet.h"

#include <filesystem>
#include <fstream>

namespace rgnav::testing {

std::vector<ClusterModule> motionAndTasks(const std::string& dir) {
  const std::string simulation = dir + "/noiseless.yaml";
  std::ofstream(simulation) << "odometry: {alpha1: 0, alpha2: 0, alpha3: 0, alpha4: 0}\n"
                               "laser: {range_noise_sigma_m: 0}\n";
  const std::string world = std::filesystem::absolute("tests/worlds/hallway_two_rooms.yaml").string();
  return {{"Simulator",
           {TestCluster::program("rgnav-sim"), "--world", world, "--config", simulation, "--clock", "realtime",
            "--start", "1,1,0"},
           {"Laser", "Base", "GroundTruth"}},
          {"LowLevelDrive",
           {TestCluster::program("rgnav-lowleveldrive"), "--config", TestCluster::moduleConfig("lowleveldrive")},
           {"LowLevelDrive"},
           {"Simulator"}},
          {"CollisionAvoidance",
           {TestCluster::program("rgnav-collisionavoidance"), "--config",
            TestCluster::moduleConfig("collisionavoidance"), "--pose-source", "odometry"},
           {"CollisionAvoidance"},
           {"Simulator", "LowLevelDrive", "PathPlanning"}},
          {"HighLevelPlanning",
           {TestCluster::program("rgnav-highlevelplanning"), "--config",
            TestCluster::moduleConfig("highlevelplanning"), "--pose-source", "scanmapper"},
           {"HighLevelPlanning"},
           {"RGMappingKernel", "CollisionAvoidance"}}};
}

std::vector<ClusterModule> mappingModules() {
  return {{"ScanMapper",
           {TestCluster::program("rgnav-scanmapper"), "--config", TestCluster::moduleConfig("scanmapper")},
           {"ScanMapper"},
           {"Simulator"}},
          {"GatewayDetection",
           {TestCluster::program("rgnav-gatewaydetection"), "--config", TestCluster::moduleConfig("gatewaydetection"),
            "--models", std::filesystem::absolute("config/gateways/gateway-hmms.txt").string()},
           {"GatewayDetection"},
           {"Simulator"}}};
}

}  // namespace rgnav::testing
