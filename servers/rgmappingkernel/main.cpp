// rgnav-rgmappingkernel: the RG Mapping Kernel module (thesis 2, 5.2, 6.1): follows the
// ScanMapper and GatewayDetection modules by ID, keeps the Region & Gateway Map consistent,
// serves regions, gateways, the RG graph, paths, names, merges and its events, exports the map,
// and resumes from its checkpoint after a restart.
#include <iostream>

#include "core/rgmap/kernel/RgMappingKernelConfigYaml.h"
#include "servers/rgmappingkernel/RgMappingKernelImpl.h"

namespace po = boost::program_options;
using namespace rgnav;

int main(int argc, char** argv) {
  std::string scanMapperObject, detectionObject, objectName, configFile, exportRoot;
  std::uint32_t maxBatch = 0, fetch = 0;
  po::options_description options("RGMappingKernel options");
  options.add_options()
      ("scanmapper-object", po::value(&scanMapperObject)->default_value("ScanMapper"), "ScanMapper module to follow")
      ("detection-object", po::value(&detectionObject)->default_value("GatewayDetection"),
       "GatewayDetection module to follow")
      ("object", po::value(&objectName)->default_value("RGMappingKernel"), "object name of the interface")
      ("config", po::value(&configFile)->required(), "module parameters (config/modules/rgmappingkernel.yaml)")
      ("fetch", po::value(&fetch)->default_value(100), "records asked from each input per call")
      ("max-batch", po::value(&maxBatch)->default_value(500), "most events one call returns")
      ("export-root", po::value(&exportRoot)->default_value(""),
       "the only directory exportMap writes into (default: <run dir>/exports beside the state directories)");
  std::unique_ptr<RgMappingKernelService> service;
  const int code = runServer(argc, argv, options, [&](ServerRuntime& runtime) {
    const RgMappingKernelConfig config = loadRgMappingKernelConfig(configFile);
    RgMappingKernelServiceOptions serviceOptions;
    serviceOptions.fetchBatch = fetch;
    if (!runtime.server().stateDir.empty()) serviceOptions.checkpointFile = runtime.server().stateDir + "/rgmap.state";
    ClientSettings settings = runtime.clientSettings();
    settings.retryBudget = std::chrono::milliseconds(2000);
    service = std::make_unique<RgMappingKernelService>(config, settings, scanMapperObject,
                                                       detectionObject, serviceOptions, runtime.health());
    const ExportRoot root(exportRoot.empty() ? defaultExportRoot(runtime.server().stateDir) : exportRoot);
    runtime.activate(objectName, new RgMappingKernelImpl(runtime, *service, maxBatch, root));
    runtime.onShutdown([&] { service->stop(); });
    service->start();
    std::cerr << "RG mapping kernel following " << scanMapperObject << " and " << detectionObject
              << ", resuming after scan " << service->summary().lastScan << ", exporting into " << root.path() << ", serving on "
              << runtime.server().endpoint.str() << std::endl;
  });
  return code;
}
