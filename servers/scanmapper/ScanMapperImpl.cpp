// The ScanMapper.idl servant (see ScanMapperImpl.h).
#include "servers/scanmapper/ScanMapperImpl.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/scanmapper/convert.h"
#include "servers/common/WireChecks.h"

namespace rgnav {
namespace {

constexpr Raises kArgs = Raises::InvalidArgument;
constexpr Raises kLookup = Raises::InvalidArgument | Raises::NotAvailable;

RGNav::PoseUpdateSeq* newUpdateSeq(const std::vector<PoseUpdate>& updates) {
  return new RGNav::PoseUpdateSeq(toIdlSeq<RGNav::PoseUpdateSeq>(updates, [](const PoseUpdate& u) { return toIdl(u); }));
}

}  // namespace

ScanMapperImpl::ScanMapperImpl(ServerRuntime& runtime, ScanMapperService& service, std::uint32_t maxBatch)
    : ServiceServant(runtime), service_(service), maxBatch_(maxBatch) {}

RGNav::DataId ScanMapperImpl::latestCorrectedId() {
  return serve(Raises::FailedOnly, [&] { return service_.latestCorrectedId(); });
}

CORBA::ULongLong ScanMapperImpl::revision() {
  return serve(Raises::FailedOnly, [&] { return service_.revision(); });
}

RGNav::CorrectedScanBatch* ScanMapperImpl::correctedSince(RGNav::DataId afterId, CORBA::ULong maxCount,
                                                          const char* consumer) {
  return serve(kArgs, [&] {
    const std::size_t count = wire::cappedCount(maxCount, maxBatch_, "maxCount");
    wire::checkedName(consumer, "consumer");
    const CorrectedBatch batch = service_.correctedSince(afterId, count);
    runtime_.health().add("corrected_scans_served", batch.scans.size());
    return new RGNav::CorrectedScanBatch(toIdl(batch));
  });
}

RGNav::PoseUpdateSeq* ScanMapperImpl::poses(RGNav::DataId firstId, RGNav::DataId lastId) {
  return serve(kLookup, [&] {
    wire::requireIdRange(firstId, lastId, "firstId", "lastId");
    return newUpdateSeq(service_.poses(firstId, lastId, maxBatch_ * 20));
  });
}

RGNav::PoseRevisionSeq* ScanMapperImpl::revisionsSince(CORBA::ULongLong afterRevision, const char* follower) {
  return serve(kArgs, [&] {
    const auto revisions = service_.revisionsSince(afterRevision, wire::checkedName(follower, "follower"));
    return new RGNav::PoseRevisionSeq(
        toIdlSeq<RGNav::PoseRevisionSeq>(revisions, [](const PoseRevisionInfo& r) { return toIdl(r); }));
  });
}

RGNav::PoseUpdateSeq* ScanMapperImpl::revisedPoses(CORBA::ULongLong revision, RGNav::DataId firstId,
                                                   RGNav::DataId lastId) {
  return serve(kLookup, [&] {
    wire::requireIdRange(firstId, lastId, "firstId", "lastId");
    return newUpdateSeq(service_.revisedPoses(revision, firstId, lastId, maxBatch_ * 20));
  });
}

RGNav::Pose2D ScanMapperImpl::correctedPose(RGNav::DataId scanId) {
  return serve(kLookup, [&] {
    wire::requireId(scanId, "scanId");
    return toIdl(service_.correctedPose(scanId));
  });
}

RGNav::Pose2D ScanMapperImpl::odomToMap(RGNav::DataId scanId, const RGNav::Pose2D& odometryPose) {
  return serve(kLookup, [&] {
    wire::requireId(scanId, "scanId");
    wire::requireFinite(odometryPose, "odometryPose");
    return toIdl(service_.odomToMap(scanId, fromIdl(odometryPose)));
  });
}

}  // namespace rgnav
