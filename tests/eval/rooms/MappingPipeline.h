// MappingPipeline: the mapping chain of the RG Nav server set (thesis 5.2: ScanMapper ->
// GatewayDetection -> RG Mapping Kernel) run in one process on a stream of scans, for the room
// evaluation (issue 7, "rgctl eval rooms"). Per scan, in ID order:
//   1. the ScanMapper (SLAM) takes the scan with its raw odometry and gives its corrected pose;
//   2. the kernel stacks the scan with that corrected pose;
//   3. the GatewayDetector sees the scan with its ODOMETRY pose (as the GatewayDetection module
//      does: its gateways are in the odometry frame), and each event it causes goes to the kernel
//      with the kernel's corrected pose of the gateway's last scan (the kernel places it with
//      corrected ∘ odometry⁻¹ of that scan).
// Whenever the ScanMapper optimised its pose graph, the kernel's poses are revised (as the kernel
// module does when the ScanMapper reports revised poses); finish() closes pending loops and
// revises them with the final SLAM poses.
// For measuring what SLAM errors cost, addScanAt gives the corrected pose instead (e.g. the true
// pose): the ScanMapper is then not used at all.
// The kernel is fed by the same KernelFeed (core/rgmap/feed) as in the kernel module, from
// in-process inputs, so the order and the poses are the module's and the server set maps a log
// as this chain does. Where it differs from the server set: no CORBA, no checkpoints.
#pragma once

#include <memory>
#include <mutex>
#include <optional>

#include "core/rgmap/feed/InProcessInputs.h"
#include "core/rgmap/feed/KernelFeed.h"
#include "tests/eval/rooms/GivenPoseScans.h"

namespace rgnav {

struct MappingPipelineConfig {
  SlamConfig slam;
  GatewayDetectorConfig gateways;
  RgMappingKernelConfig kernel;
};

// The parameters the server set runs the three modules with (config/modules, ShippedConfig.h).
MappingPipelineConfig shippedPipelineConfig();

struct MappingCounts {
  std::size_t scans = 0;
  std::size_t keyframes = 0;
  std::size_t gatewayEvents = 0;
  std::size_t traversals = 0;
};

class MappingPipeline {
 public:
  // `classifier` empty: the detector finds narrow passages only. Throws ConfigError for a bad
  // configuration (as the parts do).
  MappingPipeline(const MappingPipelineConfig& config, std::optional<HmmClassifier> classifier);

  // The next scan; scan.odometry is its raw odometry pose. IDs must increase (InvalidArgumentError).
  // One pipeline takes either addScan (SLAM) or addScanAt (given poses) throughout
  // (InvalidArgumentError otherwise).
  void addScan(const LaserScan& scan);
  void addScanAt(const LaserScan& scan, const Pose2D& corrected);
  // With SLAM: optimises pending loops and revises every pose the kernel holds with the final
  // SLAM poses. With given poses: nothing to revise.
  void finish();

  // The corrected pose of a scan taken in (NotAvailableError for an unknown ID).
  Pose2D correctedPose(DataId scanId) const;
  const RgMappingKernel& kernel() const { return kernel_; }
  // For what a user asks of the map (naming regions); the chain runs in the caller's thread.
  RgMappingKernel& kernel() { return kernel_; }
  const MappingCounts& counts() const { return counts_; }

 private:
  // Detects on the scan and feeds the kernel from `scans` as far as the inputs allow.
  void map(const LaserScan& scan, CorrectedScanInput& scans);
  void feedAll();

  InProcessScanMapper slam_;
  std::optional<GivenPoseScans> given_;  // set once addScanAt was used
  InProcessGatewayDetection detection_;
  std::mutex kernelMutex_;  // the feed's lock on the kernel; the chain runs in one thread
  RgMappingKernel kernel_;
  std::unique_ptr<KernelFeed> feed_;  // made at the first scan, from the input it brings
  MappingCounts counts_;
};

}  // namespace rgnav
