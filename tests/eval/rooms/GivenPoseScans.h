// GivenPoseScans: scans with corrected poses given by the caller (e.g. the simulator's true
// poses) as the kernel's scan input, in place of the ScanMapper, for measuring what SLAM errors
// cost the room scores. Each scan's pose as mapped is its given pose; there are no revisions.
#pragma once

#include <vector>

#include "core/rgmap/feed/MappingInputs.h"

namespace rgnav {

class GivenPoseScans : public CorrectedScanInput {
 public:
  // IDs must increase (InvalidArgumentError).
  void add(const LaserScan& scan, const Pose2D& corrected);
  void finish() { ended_ = true; }
  // NotAvailableError for an ID not given.
  Pose2D correctedPose(DataId scanId) const;

  CorrectedBatch correctedSince(DataId afterId, std::uint32_t maxCount) override;
  std::vector<PoseRevisionInfo> revisionsSince(std::uint64_t) override { return {}; }
  // NotAvailableError: no revision is ever made.
  std::vector<PoseUpdate> revisedPoses(std::uint64_t revision, DataId firstId, DataId lastId) override;
  std::vector<PoseUpdate> poses(DataId firstId, DataId lastId) override;
  std::uint64_t revision() override { return 0; }

 private:
  std::vector<CorrectedScan> scans_;
  bool ended_ = false;
};

}  // namespace rgnav
