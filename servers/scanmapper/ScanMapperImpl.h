// ScanMapperImpl: the ScanMapper.idl servant: convert in, ScanMapperService call, convert out.
#pragma once

#include "ScanMapper.hh"
#include "servers/common/ServiceServant.h"
#include "servers/scanmapper/ScanMapperService.h"

namespace rgnav {

class ScanMapperImpl : public ServiceServant<POA_RGNav::ScanMapper> {
 public:
  ScanMapperImpl(ServerRuntime& runtime, ScanMapperService& service, std::uint32_t maxBatch);

  RGNav::DataId latestCorrectedId() override;
  CORBA::ULongLong revision() override;
  RGNav::CorrectedScanBatch* correctedSince(RGNav::DataId afterId, CORBA::ULong maxCount, const char* consumer) override;
  RGNav::PoseUpdateSeq* poses(RGNav::DataId firstId, RGNav::DataId lastId) override;
  RGNav::PoseRevisionSeq* revisionsSince(CORBA::ULongLong afterRevision, const char* follower) override;
  RGNav::PoseUpdateSeq* revisedPoses(CORBA::ULongLong revision, RGNav::DataId firstId, RGNav::DataId lastId) override;
  RGNav::Pose2D correctedPose(RGNav::DataId scanId) override;
  RGNav::Pose2D odomToMap(RGNav::DataId scanId, const RGNav::Pose2D& odometryPose) override;

 private:
  ScanMapperService& service_;
  std::uint32_t maxBatch_;
};

}  // namespace rgnav
