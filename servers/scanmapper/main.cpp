// rgnav-scanmapper: the ScanMapper module (thesis 5.2): follows the Laser module by ID, aligns
// the scans with the SLAM core, serves corrected scans and poses by the same IDs, and resumes
// from its checkpoint after a restart.
#include <iostream>

#include "core/slam/SlamConfigYaml.h"
#include "servers/scanmapper/ScanMapperImpl.h"

namespace po = boost::program_options;
using namespace rgnav;

int main(int argc, char** argv) {
  std::string laserObject, objectName, configFile;
  std::vector<std::string> revisionFollowers;
  std::size_t buffer = 0;
  std::uint32_t maxBatch = 0, fetch = 0;
  po::options_description options("ScanMapper options");
  options.add_options()
      ("laser-object", po::value(&laserObject)->default_value("Laser"), "Laser module to follow")
      ("object", po::value(&objectName)->default_value("ScanMapper"), "object name of the ScanMapper interface")
      ("config", po::value(&configFile)->required(), "module parameters (config/modules/scanmapper.yaml)")
      ("buffer", po::value(&buffer)->default_value(20000), "corrected scans held for consumers")
      ("fetch", po::value(&fetch)->default_value(100), "scans asked from the Laser module per call")
      ("max-batch", po::value(&maxBatch)->default_value(500), "most records one call returns")
      ("revision-follower", po::value(&revisionFollowers)->multitoken()->default_value({"RGMappingKernel"}, "RGMappingKernel"),
       "module whose revisionsSince calls decide which pose revisions are kept (repeatable)");
  std::unique_ptr<ScanMapperService> service;
  const int code = runServer(argc, argv, options, [&](ServerRuntime& runtime) {
    const SlamConfig config = loadSlamConfig(configFile);
    ScanMapperServiceOptions serviceOptions;
    serviceOptions.bufferCapacity = buffer;
    serviceOptions.fetchBatch = fetch;
    serviceOptions.revisionFollowers = {revisionFollowers.begin(), revisionFollowers.end()};
    if (!runtime.server().stateDir.empty()) serviceOptions.checkpointFile = runtime.server().stateDir + "/slam.state";
    ClientSettings laserSettings = runtime.clientSettings();
    laserSettings.retryBudget = std::chrono::milliseconds(2000);
    service = std::make_unique<ScanMapperService>(config, laserSettings, laserObject, serviceOptions,
                                                  runtime.health());
    runtime.activate(objectName, new ScanMapperImpl(runtime, *service, maxBatch));
    runtime.onShutdown([&] { service->stop(); });
    service->start();
    std::cerr << "scan mapper following " << laserObject << ", resuming after scan " << service->latestCorrectedId()
              << ", serving on " << runtime.server().endpoint.str() << std::endl;
  });
  return code;
}
