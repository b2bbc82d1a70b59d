// rgnav-localization: the Localization module (thesis 5.3): region Monte Carlo localization in
// the RG Mapping Kernel's map on the Laser module's scans and odometry; serves the estimate of
// every scan by ID, the particles, setPose and relocalize, reports confirmed gateway traversals
// to the kernel, and resumes its particle set from its checkpoint after a restart.
#include <iostream>

#include "core/nav/localization/MclConfigYaml.h"
#include "servers/localization/LocalizationImpl.h"

namespace po = boost::program_options;
using namespace rgnav;

int main(int argc, char** argv) {
  std::string laserObject, kernelObject, objectName, configFile;
  std::uint32_t maxParticles = 0;
  LocalizationServiceOptions serviceOptions;
  double sigmaXy = 0.0, sigmaTheta = 0.0;
  po::options_description options("Localization options");
  options.add_options()
      ("laser-object", po::value(&laserObject)->default_value("Laser"), "Laser module whose scans are localized")
      ("kernel-object", po::value(&kernelObject)->default_value("RGMappingKernel"), "RG Mapping Kernel module to localize in")
      ("object", po::value(&objectName)->default_value("Localization"), "object name of the interface")
      ("config", po::value(&configFile)->required(), "module parameters (config/modules/localization.yaml)")
      ("max-particles", po::value(&maxParticles)->default_value(10000), "most particles one particles() call returns")
      ("history", po::value(&serviceOptions.historyScans)->default_value(serviceOptions.historyScans), "scans whose estimates are kept")
      ("checkpoint-interval", po::value(&serviceOptions.checkpointIntervalS)->default_value(serviceOptions.checkpointIntervalS),
       "s between checkpoints of the particle set (at least)")
      ("map-refresh", po::value(&serviceOptions.mapRefreshS)->default_value(serviceOptions.mapRefreshS),
       "s between looks at the kernel's map summary (at least)")
      ("start-at-odometry", po::bool_switch(&serviceOptions.startAtOdometry),
       "take the first scan's odometry pose as the initial guess (a map made by a ScanMapper from this robot's start)")
      ("mapped-scans-only", po::bool_switch(&serviceOptions.mappedScansOnly),
       "take only scans the kernel has mapped (a map made online by a faster-than-real-time simulation)")
      ("start-sigma-xy", po::value(&sigmaXy)->default_value(0.1), "m: that guess's standard deviation in x and y")
      ("start-sigma-theta", po::value(&sigmaTheta)->default_value(0.05), "rad: and in the heading")
      ("seed", po::value(&serviceOptions.seed)->default_value(1), "random seed of the filter");
  std::unique_ptr<LocalizationService> service;
  return runServer(argc, argv, options, [&](ServerRuntime& runtime) {
    const MclConfig config = loadMclConfig(configFile);
    serviceOptions.startSigma = {sigmaXy, sigmaXy, sigmaTheta};
    if (!runtime.server().stateDir.empty()) serviceOptions.checkpointFile = runtime.server().stateDir + "/particles.state";
    service = std::make_unique<LocalizationService>(config, runtime.clientSettings(), laserObject, kernelObject,
                                                    serviceOptions, runtime.health());
    runtime.activate(objectName, new LocalizationImpl(runtime, *service, maxParticles));
    runtime.onShutdown([&] { service->stop(); });
    service->start();
    std::cerr << "localization on " << laserObject << " in " << kernelObject << ", serving on "
              << runtime.server().endpoint.str() << std::endl;
  });
}
