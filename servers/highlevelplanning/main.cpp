// rgnav-highlevelplanning: the High-Level Planning module (thesis chapter 1, figure 5.1, 6.1.3,
// chapter 7): a queue of tasks (go to a point, a region or an object by name; explore; stop)
// carried out one at a time through the CollisionAvoidance module, their state by ID, and the
// naming dialog's questions about unnamed regions; resumes its tasks and questions from its
// checkpoint after a restart.
#include <iostream>

#include "core/nav/tasks/HighLevelPlanningConfigYaml.h"
#include "servers/highlevelplanning/HighLevelPlanningImpl.h"

namespace po = boost::program_options;
using namespace rgnav;

int main(int argc, char** argv) {
  std::string configFile, objectName;
  HighLevelPlanningServiceOptions serviceOptions;
  po::options_description options("HighLevelPlanning options");
  options.add_options()
      ("config", po::value(&configFile)->required(), "module parameters (config/modules/highlevelplanning.yaml)")
      ("pose-source", po::value(&serviceOptions.poseSource)->default_value("scanmapper"),
       "scanmapper (the ScanMapper's corrected pose: while mapping) or localization (a known map)")
      ("pose-object", po::value(&serviceOptions.poseObject)->default_value(""),
       "object name of the pose source (default ScanMapper or Localization)")
      ("strategy", po::value(&serviceOptions.strategy)->default_value("rg"),
       "exploration strategy: rg (region by region, thesis chapter 7) or frontier (nearest frontier)")
      ("kernel-object", po::value(&serviceOptions.kernelObject)->default_value("RGMappingKernel"),
       "RG Mapping Kernel module: the map, the current region, names")
      ("avoidance-object", po::value(&serviceOptions.avoidanceObject)->default_value("CollisionAvoidance"),
       "CollisionAvoidance module that drives")
      ("object", po::value(&objectName)->default_value("HighLevelPlanning"), "object name of the interface");
  std::unique_ptr<HighLevelPlanningService> service;
  const int code = runServer(argc, argv, options, [&](ServerRuntime& runtime) {
    const HighLevelPlanningConfig config = loadHighLevelPlanningConfig(configFile);
    if (!runtime.server().stateDir.empty()) serviceOptions.checkpointFile = runtime.server().stateDir + "/tasks.state";
    ClientSettings settings = runtime.clientSettings();
    settings.retryBudget = std::chrono::milliseconds(1000);
    service = std::make_unique<HighLevelPlanningService>(config, settings, serviceOptions, runtime.health());
    runtime.activate(objectName, new HighLevelPlanningImpl(runtime, *service));
    service->start();
    runtime.onShutdown([&] { service->stop(); });
    std::cerr << "high-level planning (pose source " << serviceOptions.poseSource << ", strategy "
              << serviceOptions.strategy << ", next task " << service->nextTaskId() << ") serving on "
              << runtime.server().endpoint.str() << std::endl;
  });
  if (service) service->stop();
  return code;
}
