// ScanMapperClient: corrected scans and poses by scan ID from the ScanMapper module.
#pragma once

#include <vector>

#include "ScanMapper.hh"
#include "clientlibs/common/ModuleClient.h"
#include "core/slam/CorrectedScans.h"

namespace rgnav {

class ScanMapperClient : public ModuleClientOf<RGNav::ScanMapper> {
 public:
  explicit ScanMapperClient(ClientSettings settings = ClientSettings::fromEnvironment(),
                            std::string objectName = "ScanMapper");

  DataId latestCorrectedId();
  std::uint64_t revision();
  CorrectedBatch correctedSince(DataId afterId, std::uint32_t maxCount);
  std::vector<PoseUpdate> poses(DataId firstId, DataId lastId);
  // As the follower named by the settings' consumer, which has durably applied every revision up
  // to afterRevision (ScanMapper.idl).
  std::vector<PoseRevisionInfo> revisionsSince(std::uint64_t afterRevision);
  // NotAvailableError if the revision is no longer kept (ScanMapper.idl).
  std::vector<PoseUpdate> revisedPoses(std::uint64_t revision, DataId firstId, DataId lastId);
  Pose2D correctedPose(DataId scanId);
  Pose2D odomToMap(DataId scanId, const Pose2D& odometryPose);

 private:
  std::string consumer_;
};

}  // namespace rgnav
