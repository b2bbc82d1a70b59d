// The in-process mapping chain; see MappingPipeline.h.
#include "tests/eval/rooms/MappingPipeline.h"

#include "core/common/Errors.h"
#include "core/config/ShippedConfig.h"
#include "core/gateways/detection/GatewayDetectorConfigYaml.h"
#include "core/rgmap/kernel/RgMappingKernelConfigYaml.h"
#include "core/slam/SlamConfigYaml.h"

namespace rgnav {
namespace {

constexpr std::uint32_t kFetchBatch = 100;  // as the kernel module's default

}  // namespace

MappingPipelineConfig shippedPipelineConfig() {
  return {loadSlamConfig(shippedConfigFile("modules/scanmapper.yaml")),
          loadGatewayDetectorConfig(shippedConfigFile("modules/gatewaydetection.yaml")),
          loadRgMappingKernelConfig(shippedConfigFile("modules/rgmappingkernel.yaml"))};
}

MappingPipeline::MappingPipeline(const MappingPipelineConfig& config, std::optional<HmmClassifier> classifier)
    : slam_(config.slam), detection_(config.gateways, std::move(classifier)), kernel_(config.kernel) {}

void MappingPipeline::addScan(const LaserScan& scan) {
  if (given_) throw InvalidArgumentError("mapping pipeline: SLAM poses after given poses");
  counts_.keyframes += slam_.add(scan).keyframe;
  map(scan, slam_);
}

void MappingPipeline::addScanAt(const LaserScan& scan, const Pose2D& corrected) {
  if (!given_) {
    if (counts_.scans > 0) throw InvalidArgumentError("mapping pipeline: given poses after SLAM poses");
    given_.emplace();
  }
  given_->add(scan, corrected);
  map(scan, *given_);
}

void MappingPipeline::map(const LaserScan& scan, CorrectedScanInput& scans) {
  if (!feed_) feed_ = std::make_unique<KernelFeed>(kernel_, kernelMutex_, scans, detection_, kFetchBatch);
  for (const GatewayEvent& event : detection_.add(scan)) {
    ++counts_.gatewayEvents;
    counts_.traversals += event.kind == GatewayEventKind::Traversed;
  }
  ++counts_.scans;
  feedAll();
}

void MappingPipeline::feedAll() {
  while (feed_->step()) {
  }
}

Pose2D MappingPipeline::correctedPose(DataId scanId) const {
  return given_ ? given_->correctedPose(scanId) : slam_.mapper().correctedPose(scanId);
}

void MappingPipeline::finish() {
  if (!feed_) return;
  if (given_) {
    given_->finish();
  } else {
    slam_.finish();
  }
  detection_.finish();
  feedAll();
}

}  // namespace rgnav
