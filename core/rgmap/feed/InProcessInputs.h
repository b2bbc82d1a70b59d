// The kernel's two inputs run in the caller's process: the SLAM core and the gateway detector
// behind the interfaces of MappingInputs.h, serving what the ScanMapper and GatewayDetection
// modules would (PoseQueries.h), so the in-process mapping chain feeds the kernel exactly as the
// kernel module does (KernelFeed.h). They keep every scan and event they were given.
#pragma once

#include <optional>
#include <vector>

#include "core/gateways/detection/GatewayDetector.h"
#include "core/rgmap/feed/MappingInputs.h"
#include "core/slam/ScanMapper.h"

namespace rgnav {

class InProcessScanMapper : public CorrectedScanInput {
 public:
  explicit InProcessScanMapper(const SlamConfig& config);

  // Maps the next scan (raw odometry in scan.odometry; IDs increase: InvalidArgumentError).
  ScanOutcome add(const LaserScan& scan);
  // The input ended: optimises pending loops; endOfData from now on.
  void finish();
  const ScanMapper& mapper() const { return slam_; }

  CorrectedBatch correctedSince(DataId afterId, std::uint32_t maxCount) override;
  std::vector<PoseRevisionInfo> revisionsSince(std::uint64_t afterRevision) override;
  std::vector<PoseUpdate> revisedPoses(std::uint64_t revision, DataId firstId, DataId lastId) override;
  std::vector<PoseUpdate> poses(DataId firstId, DataId lastId) override;
  std::uint64_t revision() override;

 private:
  ScanMapper slam_;
  std::vector<LaserScan> scans_;
  bool ended_ = false;
};

class InProcessGatewayDetection : public GatewayEventInput {
 public:
  // `classifier` empty: narrow passages only.
  InProcessGatewayDetection(const GatewayDetectorConfig& config, std::optional<HmmClassifier> classifier);

  // Detects on the next scan at its odometry pose (the module's frame); returns the events it caused.
  const std::vector<GatewayEvent>& add(const LaserScan& scan);
  void finish() { ended_ = true; }

  GatewayEventBatch eventsSince(GatewayEventId afterId, std::uint32_t maxCount) override;

 private:
  GatewayDetector detector_;
  std::vector<GatewayEvent> events_;
  std::vector<GatewayEvent> latest_;
  bool ended_ = false;
};

}  // namespace rgnav
