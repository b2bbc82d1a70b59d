// rgnav-collisionavoidance: the CollisionAvoidance module (thesis 5.5.3): follows the Laser's scans
// and the Base's odometry, keeps a laser obstacle grid, and drives the PathPlanning module's target
// poses (driveTo) or given targets (followTargets) with chains of trajectory primitives checked
// against the obstacles and sent to the Low-Level Drive; waits when no chain is free and plans
// again when the way stays blocked; resumes its drive from its checkpoint after a restart.
#include <iostream>

#include "core/nav/avoidance/CollisionAvoidanceConfigYaml.h"
#include "servers/collisionavoidance/CollisionAvoidanceImpl.h"

namespace po = boost::program_options;
using namespace rgnav;

namespace {

// "disk:R" or "rectangle:LENGTH,WIDTH[,CENTER_OFFSET]" (metres).
Footprint parseFootprint(const std::string& text) {
  double a = 0, b = 0, c = 0;
  if (std::sscanf(text.c_str(), "disk:%lf", &a) == 1) return Footprint::disk(a);
  const int n = std::sscanf(text.c_str(), "rectangle:%lf,%lf,%lf", &a, &b, &c);
  if (n >= 2) return Footprint::rectangle(a, b, c);
  throw ConfigError("--footprint is disk:R or rectangle:LENGTH,WIDTH[,OFFSET], not '" + text + "'");
}

}  // namespace

int main(int argc, char** argv) {
  std::string configFile, poseSource, footprint, objectName;
  AvoidanceServiceOptions serviceOptions;
  po::options_description options("CollisionAvoidance options");
  options.add_options()
      ("config", po::value(&configFile)->required(), "module parameters (config/modules/collisionavoidance.yaml)")
      ("pose-source", po::value(&poseSource)->default_value("odometry"),
       "odometry (map frame = odometry frame), groundtruth (the simulator's true pose; evaluations), scanmapper "
       "(the ScanMapper's corrected poses: while mapping) or localization (the Localization module's estimate: a known map)")
      ("footprint", po::value(&footprint)->default_value("disk:0.25"), "the robot's outline: disk:R or rectangle:L,W[,OFFSET]")
      ("laser-object", po::value(&serviceOptions.laserObject)->default_value("Laser"), "Laser module to follow")
      ("base-object", po::value(&serviceOptions.baseObject)->default_value("Base"), "Base module for odometry")
      ("truth-object", po::value(&serviceOptions.truthObject)->default_value("GroundTruth"), "GroundTruth (pose source groundtruth)")
      ("scanmapper-object", po::value(&serviceOptions.scanMapperObject)->default_value("ScanMapper"), "ScanMapper (pose source scanmapper)")
      ("localization-object", po::value(&serviceOptions.localizationObject)->default_value("Localization"),
       "Localization (pose source localization)")
      ("drive-object", po::value(&serviceOptions.driveObject)->default_value("LowLevelDrive"), "Low-Level Drive to send chains to")
      ("planner-object", po::value(&serviceOptions.plannerObject)->default_value("PathPlanning"), "PathPlanning module to ask for plans")
      ("object", po::value(&objectName)->default_value("CollisionAvoidance"), "object name of the interface")
      ("trace", po::bool_switch(&serviceOptions.trace), "log every decision but keep");
  std::unique_ptr<AvoidanceService> service;
  const int code = runServer(argc, argv, options, [&](ServerRuntime& runtime) {
    const CollisionAvoidanceConfig config = loadCollisionAvoidanceConfig(configFile);
    serviceOptions.poseSource = parsePoseSource(poseSource);
    serviceOptions.footprint = parseFootprint(footprint);
    if (!runtime.server().stateDir.empty()) serviceOptions.checkpointFile = runtime.server().stateDir + "/drive.state";
    ClientSettings settings = runtime.clientSettings();
    settings.retryBudget = std::chrono::milliseconds(1000);
    service = std::make_unique<AvoidanceService>(config, settings, serviceOptions, runtime.health());
    runtime.activate(objectName, new CollisionAvoidanceImpl(runtime, *service));
    service->start();
    runtime.onShutdown([&] { service->stop(); });
    std::cerr << "collision avoidance (pose source " << poseSource << ", resuming drive "
              << service->status().request << " " << toString(service->status().phase) << ") serving on "
              << runtime.server().endpoint.str() << std::endl;
  });
  if (service) service->stop();
  return code;
}
