// The crowd evaluation's server set (see CrowdSet.h).
#include "tests/eval/crowd/CrowdSet.h"

#include <cstdio>
#include <filesystem>

#include "tests/eval/crowd/OfficeRgMap.h"
#include "tests/integration/PlanningSet.h"

namespace rgnav {

using testing::ClusterModule;
using testing::TestCluster;

namespace {

std::string poseArgument(const Pose2D& p) {
  char text[96];
  std::snprintf(text, sizeof text, "%.3f,%.3f,%.4f", p.x, p.y, p.theta);
  return text;
}

std::vector<std::string> simulatorCommand(const CrowdSetOptions& o) {
  return {TestCluster::program("rgnav-sim"), "--world", std::filesystem::absolute(o.world).string(), "--config",
          std::filesystem::absolute(o.simConfig).string(), "--clock", "realtime",
          "--start", poseArgument(o.start), "--people", std::to_string(o.people), "--seed", std::to_string(o.seed)};
}

// The set: the simulator with the Low-Level Drive, the kernel and the PathPlanning module as the
// PathPlanning module's tests run them (planningModules), the Collision Avoidance on the true pose.
std::vector<ClusterModule> crowdModules(const CrowdSetOptions& o) {
  std::vector<ClusterModule> modules{
      {"Simulator", simulatorCommand(o), {"Laser", "Base", "GroundTruth"}},
      {"LowLevelDrive",
       {TestCluster::program("rgnav-lowleveldrive"), "--config", TestCluster::moduleConfig("lowleveldrive")},
       {"LowLevelDrive"},
       {"Simulator"}}};
  for (ClusterModule& m : testing::planningModules()) modules.push_back(std::move(m));
  modules.push_back({"CollisionAvoidance",
                     {TestCluster::program("rgnav-collisionavoidance"), "--config",
                      TestCluster::moduleConfig("collisionavoidance"), "--pose-source", "groundtruth", "--trace"},
                     {"CollisionAvoidance"},
                     {"Simulator", "LowLevelDrive", "PathPlanning"}});
  return modules;
}

}  // namespace

CrowdSet::CrowdSet(const CrowdSetOptions& o, const RgMapState* map)
    : cluster_(std::make_unique<TestCluster>(crowdModules(o), o.setYaml)) {
  if (map) writeKernelCheckpoint(*map, cluster_->dir() + "/run/state/RGMappingKernel");
}

void CrowdSet::start() { cluster_->start(); }

}  // namespace rgnav
