// rgnav-gatewaydetection: the GatewayDetection module (thesis 5.2): follows the Laser module by
// ID, detects narrow passages (4.2.1) and, with trained HMMs (config/gateways), turns, junctions
// and crossings (4.1), serves its buffer of gateway hypotheses as events by ID, and resumes from
// its checkpoint after a restart.
#include <iostream>

#include "core/gateways/classify/HmmModelFile.h"
#include "core/gateways/detection/GatewayDetectorConfigYaml.h"
#include "servers/gatewaydetection/GatewayDetectionImpl.h"

namespace po = boost::program_options;
using namespace rgnav;

int main(int argc, char** argv) {
  std::string laserObject, objectName, models, configFile;
  std::uint32_t maxBatch = 0, fetch = 0;
  po::options_description options("GatewayDetection options");
  options.add_options()
      ("laser-object", po::value(&laserObject)->default_value("Laser"), "Laser module to follow")
      ("object", po::value(&objectName)->default_value("GatewayDetection"), "object name of the interface")
      ("models", po::value(&models)->default_value(""),
       "trained HMM file (config/gateways/gateway-hmms.txt); none: narrow passages only")
      ("config", po::value(&configFile)->required(), "module parameters (config/modules/gatewaydetection.yaml)")
      ("fetch", po::value(&fetch)->default_value(100), "scans asked from the Laser module per call")
      ("max-batch", po::value(&maxBatch)->default_value(500), "most events one call returns");
  std::unique_ptr<GatewayDetectionService> service;
  const int code = runServer(argc, argv, options, [&](ServerRuntime& runtime) {
    const GatewayDetectorConfig config = loadGatewayDetectorConfig(configFile);
    std::optional<HmmClassifier> classifier;
    if (!models.empty()) classifier = loadHmmModels(models);
    GatewayDetectionServiceOptions serviceOptions;
    serviceOptions.fetchBatch = fetch;
    if (!runtime.server().stateDir.empty())
      serviceOptions.checkpointFile = runtime.server().stateDir + "/gateways.state";
    ClientSettings laserSettings = runtime.clientSettings();
    laserSettings.retryBudget = std::chrono::milliseconds(2000);
    service = std::make_unique<GatewayDetectionService>(config, std::move(classifier), laserSettings, laserObject,
                                                        serviceOptions, runtime.health());
    runtime.activate(objectName, new GatewayDetectionImpl(runtime, *service, maxBatch));
    runtime.onShutdown([&] { service->stop(); });
    service->start();
    std::cerr << "gateway detection following " << laserObject << ", resuming after scan "
              << service->lastProcessedScan() << (service->detectsHallways() ? ", passages and hallway gateways" : ", narrow passages only")
              << ", serving on " << runtime.server().endpoint.str() << std::endl;
  });
  return code;
}
