// rgnav-pathplanning: the PathPlanning module (thesis 2.1.3, 5.4): plans on the RG Mapping
// Kernel's map (RG-graph route joined with framed-quadtree paths in the regions, cut into target
// poses), serves its plans by ID, replans when a door is found blocked, and resumes its plan store
// from its checkpoint after a restart.
#include <iostream>

#include "core/nav/planning/RoutePlannerConfigYaml.h"
#include "servers/pathplanning/PathPlanningImpl.h"

namespace po = boost::program_options;
using namespace rgnav;

int main(int argc, char** argv) {
  std::string kernelObject, objectName, configFile;
  std::size_t keptPlans = 0;
  po::options_description options("PathPlanning options");
  options.add_options()
      ("kernel-object", po::value(&kernelObject)->default_value("RGMappingKernel"), "RG Mapping Kernel module to plan on")
      ("object", po::value(&objectName)->default_value("PathPlanning"), "object name of the interface")
      ("config", po::value(&configFile)->required(), "module parameters (config/modules/pathplanning.yaml)")
      ("kept-plans", po::value(&keptPlans)->default_value(PlanStore::kKeptPlans), "plans kept for planById and retries");
  std::unique_ptr<PathPlanningService> service;
  return runServer(argc, argv, options, [&](ServerRuntime& runtime) {
    const RoutePlannerConfig config = loadRoutePlannerConfig(configFile);
    PathPlanningServiceOptions serviceOptions;
    serviceOptions.keptPlans = keptPlans;
    if (!runtime.server().stateDir.empty()) serviceOptions.checkpointFile = runtime.server().stateDir + "/plans.state";
    ClientSettings settings = runtime.clientSettings();
    settings.retryBudget = std::chrono::milliseconds(2000);
    service = std::make_unique<PathPlanningService>(config, settings, kernelObject, serviceOptions, runtime.health());
    runtime.activate(objectName, new PathPlanningImpl(runtime, *service));
    std::cerr << "path planning on " << kernelObject << ", resuming after plan " << service->nextPlanId() - 1
              << ", serving on " << runtime.server().endpoint.str() << std::endl;
  });
}
