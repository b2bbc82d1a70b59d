// The in-process mapping chain; see MappingPipeline.h.
#include "tests/eval/rooms/MappingPipeline.h"

#include <string>
#include <vector>

#include "core/common/Errors.h"
#include "core/config/ShippedConfig.h"
#include "core/gateways/detection/GatewayDetectorConfigYaml.h"
#include "core/rgmap/kernel/RgMappingKernelConfigYaml.h"
#include "core/slam/SlamConfigYaml.h"

namespace rgnav {

MappingPipelineConfig shippedPipelineConfig() {
  return {loadSlamConfig(shippedConfigFile("modules/scanmapper.yaml")),
          loadGatewayDetectorConfig(shippedConfigFile("modules/gatewaydetection.yaml")),
          loadRgMappingKernelConfig(shippedConfigFile("modules/rgmappingkernel.yaml"))};
}

MappingPipeline::MappingPipeline(const MappingPipelineConfig& config, std::optional<HmmClassifier> classifier)
    : slam_(config.slam), detector_(config.gateways, std::move(classifier)), kernel_(config.kernel) {}

void MappingPipeline::addScan(const LaserScan& scan) {
  if (given_) throw InvalidArgumentError("mapping pipeline: SLAM poses after given poses");
  const ScanOutcome outcome = slam_.addScan(scan);
  counts_.keyframes += outcome.keyframe;
  if (outcome.optimized) reviseKernelPoses();
  map(scan);
}

void MappingPipeline::addScanAt(const LaserScan& scan, const Pose2D& corrected) {
  if (!given_) {
    if (counts_.scans > 0) throw InvalidArgumentError("mapping pipeline: given poses after SLAM poses");
    given_.emplace();
  }
  given_->emplace(scan.id, corrected);
  map(scan);
}

void MappingPipeline::map(const LaserScan& scan) {
  kernel_.addScan(scan, correctedPose(scan.id));
  for (const GatewayEvent& event : detector_.addScan(scan, scan.odometry)) {
    kernel_.addGatewayEvent(event, kernel_.state().scans.at(event.gateway.lastScan).corrected);
    ++counts_.gatewayEvents;
    counts_.traversals += event.kind == GatewayEventKind::Traversed;
  }
  ++counts_.scans;
}

Pose2D MappingPipeline::correctedPose(DataId scanId) const {
  if (!given_) return slam_.correctedPose(scanId);
  const auto found = given_->find(scanId);
  if (found == given_->end()) throw NotAvailableError("mapping pipeline: no pose of scan " + std::to_string(scanId));
  return found->second;
}

void MappingPipeline::finish() {
  if (given_) return;
  slam_.optimize();
  reviseKernelPoses();
}

void MappingPipeline::reviseKernelPoses() {
  std::vector<CorrectedPose> poses;
  poses.reserve(kernel_.state().scans.size());
  for (const auto& [id, stored] : kernel_.state().scans) poses.push_back({id, slam_.correctedPose(id)});
  kernel_.revisePoses(poses, slam_.state().counters.optimizations);
}

}  // namespace rgnav
