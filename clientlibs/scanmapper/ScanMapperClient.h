// ScanMapperClient: corrected scans and poses by scan ID from the ScanMapper module.
#pragma once

#include <vector>

#include "ScanMapper.hh"
#include "clientlibs/common/ModuleClient.h"
#include "core/rgmap/feed/MappingInputs.h"

namespace rgnav {

// It is the kernel's scan input (MappingInputs.h) in the kernel module.
class ScanMapperClient : public ModuleClientOf<RGNav::ScanMapper>, public CorrectedScanInput {
 public:
  explicit ScanMapperClient(ClientSettings settings = ClientSettings::fromEnvironment(),
                            std::string objectName = "ScanMapper");

  DataId latestCorrectedId();
  std::uint64_t revision() override;
  CorrectedBatch correctedSince(DataId afterId, std::uint32_t maxCount) override;
  std::vector<PoseUpdate> poses(DataId firstId, DataId lastId) override;
  // As the follower named by the settings' consumer, which has durably applied every revision up
  // to afterRevision (ScanMapper.idl).
  std::vector<PoseRevisionInfo> revisionsSince(std::uint64_t afterRevision) override;
  // NotAvailableError if the revision is no longer kept (ScanMapper.idl).
  std::vector<PoseUpdate> revisedPoses(std::uint64_t revision, DataId firstId, DataId lastId) override;
  Pose2D correctedPose(DataId scanId);
  Pose2D odomToMap(DataId scanId, const Pose2D& odometryPose);

 private:
  std::string consumer_;
};

}  // namespace rgnav
