// The ScanMapper.idl servant (see ScanMapperImpl.h).
#include "servers/scanmapper/ScanMapperImpl.h"

#include <algorithm>

#include "clientlibs/common/convert.h"
#include "clientlibs/scanmapper/convert.h"
#include "servers/common/IdlErrors.h"

namespace rgnav {
namespace {

RGNav::PoseUpdateSeq* newUpdateSeq(const std::vector<PoseUpdate>& updates) {
  return new RGNav::PoseUpdateSeq(toIdlSeq<RGNav::PoseUpdateSeq>(updates, [](const PoseUpdate& u) { return toIdl(u); }));
}

}  // namespace

ScanMapperImpl::ScanMapperImpl(ServerRuntime& runtime, ScanMapperService& service, std::uint32_t maxBatch)
    : ServiceServant(runtime), service_(service), maxBatch_(maxBatch) {}

RGNav::DataId ScanMapperImpl::latestCorrectedId() { return service_.latestCorrectedId(); }

CORBA::ULongLong ScanMapperImpl::revision() { return service_.revision(); }

RGNav::CorrectedScanBatch* ScanMapperImpl::correctedSince(RGNav::DataId afterId, CORBA::ULong maxCount, const char*) {
  if (maxCount == 0) throw RGNav::InvalidArgument("maxCount must be at least 1");
  const CorrectedBatch batch = service_.correctedSince(afterId, std::min<std::size_t>(maxCount, maxBatch_));
  runtime_.health().add("corrected_scans_served", batch.scans.size());
  return new RGNav::CorrectedScanBatch(toIdl(batch));
}

RGNav::PoseUpdateSeq* ScanMapperImpl::poses(RGNav::DataId firstId, RGNav::DataId lastId) {
  const auto updates = withIdlErrors([&] { return service_.poses(firstId, lastId, maxBatch_ * 20); });
  return newUpdateSeq(updates);
}

RGNav::PoseRevisionSeq* ScanMapperImpl::revisionsSince(CORBA::ULongLong afterRevision, const char* follower) {
  const auto revisions = service_.revisionsSince(afterRevision, follower);
  return new RGNav::PoseRevisionSeq(
      toIdlSeq<RGNav::PoseRevisionSeq>(revisions, [](const PoseRevisionInfo& r) { return toIdl(r); }));
}

RGNav::PoseUpdateSeq* ScanMapperImpl::revisedPoses(CORBA::ULongLong revision, RGNav::DataId firstId,
                                                   RGNav::DataId lastId) {
  const auto updates = withIdlErrors([&] { return service_.revisedPoses(revision, firstId, lastId, maxBatch_ * 20); });
  return newUpdateSeq(updates);
}

RGNav::Pose2D ScanMapperImpl::correctedPose(RGNav::DataId scanId) {
  return toIdl(withIdlErrors([&] { return service_.correctedPose(scanId); }));
}

RGNav::Pose2D ScanMapperImpl::odomToMap(RGNav::DataId scanId, const RGNav::Pose2D& odometryPose) {
  return toIdl(withIdlErrors([&] { return service_.odomToMap(scanId, fromIdl(odometryPose)); }));
}

}  // namespace rgnav
