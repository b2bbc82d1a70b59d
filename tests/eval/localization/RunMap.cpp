// The RG map of a run from its corrected poses; see RunMap.h.
#include "tests/eval/localization/RunMap.h"

#include <chrono>
#include <filesystem>
#include <optional>

#include "core/gateways/classify/HmmModelFile.h"
#include "tests/eval/rooms/MappingPipeline.h"

namespace rgnav {

RunMap mapOfRun(std::span<const LaserScan> scans, const std::string& models) {
  std::optional<HmmClassifier> classifier;
  if (std::filesystem::exists(models)) classifier = loadHmmModels(models);
  const auto start = std::chrono::steady_clock::now();
  MappingPipeline pipeline(shippedPipelineConfig(), std::move(classifier));
  for (const LaserScan& scan : scans) pipeline.addScanAt(scan, scan.sensorPose);
  pipeline.finish();
  RunMap run{finalMapOf(pipeline.kernel()), {}, pipeline.counts().gatewayEvents, 0.0};
  for (const auto& [id, region] : pipeline.kernel().state().regions)
    for (const DataId scan : region.scans) run.scanRegions[scan] = id;
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace rgnav
