// ScanMapperClient calls through the retrying connection (see ScanMapperClient.h).
#include "clientlibs/scanmapper/ScanMapperClient.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/scanmapper/convert.h"

namespace rgnav {

ScanMapperClient::ScanMapperClient(ClientSettings settings, std::string objectName)
    : ModuleClientOf(std::move(objectName), settings), consumer_(settings.consumer) {}

DataId ScanMapperClient::latestCorrectedId() {
  return connection_.call("latestCorrectedId", [](RGNav::ScanMapper_ptr m) { return m->latestCorrectedId(); });
}

std::uint64_t ScanMapperClient::revision() {
  return connection_.call("revision", [](RGNav::ScanMapper_ptr m) { return m->revision(); });
}

CorrectedBatch ScanMapperClient::correctedSince(DataId afterId, std::uint32_t maxCount) {
  return connection_.call("correctedSince", [&](RGNav::ScanMapper_ptr m) {
    RGNav::CorrectedScanBatch_var batch = m->correctedSince(afterId, maxCount, consumer_.c_str());
    return fromIdl(batch.in());
  });
}

std::vector<PoseUpdate> ScanMapperClient::poses(DataId firstId, DataId lastId) {
  return connection_.call("poses", [&](RGNav::ScanMapper_ptr m) {
    RGNav::PoseUpdateSeq_var updates = m->poses(firstId, lastId);
    return fromIdlSeq<std::vector<PoseUpdate>>(updates.in(), [](const RGNav::PoseUpdate& u) { return fromIdl(u); });
  });
}

std::vector<PoseRevisionInfo> ScanMapperClient::revisionsSince(std::uint64_t afterRevision) {
  return connection_.call("revisionsSince", [&](RGNav::ScanMapper_ptr m) {
    RGNav::PoseRevisionSeq_var revisions = m->revisionsSince(afterRevision, consumer_.c_str());
    return fromIdlSeq<std::vector<PoseRevisionInfo>>(revisions.in(),
                                                     [](const RGNav::PoseRevision& r) { return fromIdl(r); });
  });
}

std::vector<PoseUpdate> ScanMapperClient::revisedPoses(std::uint64_t revision, DataId firstId, DataId lastId) {
  return connection_.call("revisedPoses", [&](RGNav::ScanMapper_ptr m) {
    RGNav::PoseUpdateSeq_var updates = m->revisedPoses(revision, firstId, lastId);
    return fromIdlSeq<std::vector<PoseUpdate>>(updates.in(), [](const RGNav::PoseUpdate& u) { return fromIdl(u); });
  });
}

Pose2D ScanMapperClient::correctedPose(DataId scanId) {
  return connection_.call("correctedPose", [&](RGNav::ScanMapper_ptr m) { return fromIdl(m->correctedPose(scanId)); });
}

Pose2D ScanMapperClient::odomToMap(DataId scanId, const Pose2D& odometryPose) {
  return connection_.call("odomToMap",
                          [&](RGNav::ScanMapper_ptr m) { return fromIdl(m->odomToMap(scanId, toIdl(odometryPose))); });
}

}  // namespace rgnav
