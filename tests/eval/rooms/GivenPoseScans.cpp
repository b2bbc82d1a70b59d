// Scans with given corrected poses as the kernel's scan input (see GivenPoseScans.h).
#include "tests/eval/rooms/GivenPoseScans.h"

#include <algorithm>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

std::vector<CorrectedScan>::const_iterator firstAfter(const std::vector<CorrectedScan>& scans, DataId id) {
  return std::upper_bound(scans.begin(), scans.end(), id,
                          [](DataId value, const CorrectedScan& s) { return value < s.scan.id; });
}

}  // namespace

void GivenPoseScans::add(const LaserScan& scan, const Pose2D& corrected) {
  if (!scans_.empty() && scan.id <= scans_.back().scan.id)
    throw InvalidArgumentError("given poses: scan " + std::to_string(scan.id) + " after scan " +
                               std::to_string(scans_.back().scan.id));
  scans_.push_back(CorrectedScan{scan, corrected, corrected, false});
}

Pose2D GivenPoseScans::correctedPose(DataId scanId) const {
  const auto it = firstAfter(scans_, scanId - 1);
  if (scanId == 0 || it == scans_.end() || it->scan.id != scanId)
    throw NotAvailableError("given poses: no pose of scan " + std::to_string(scanId));
  return it->corrected;
}

CorrectedBatch GivenPoseScans::correctedSince(DataId afterId, std::uint32_t maxCount) {
  CorrectedBatch out;
  out.latestId = scans_.empty() ? 0 : scans_.back().scan.id;
  for (auto it = firstAfter(scans_, afterId); it != scans_.end() && out.scans.size() < maxCount; ++it)
    out.scans.push_back(*it);
  out.endOfData = ended_ && (out.scans.empty() ? afterId : out.scans.back().scan.id) >= out.latestId;
  return out;
}

std::vector<PoseUpdate> GivenPoseScans::revisedPoses(std::uint64_t revision, DataId, DataId) {
  throw NotAvailableError("given poses: revision " + std::to_string(revision) + " was never made");
}

std::vector<PoseUpdate> GivenPoseScans::poses(DataId firstId, DataId lastId) {
  std::vector<PoseUpdate> out;
  for (auto it = firstAfter(scans_, firstId - 1); it != scans_.end() && it->scan.id <= lastId; ++it)
    out.push_back(PoseUpdate{it->scan.id, it->corrected});
  return out;
}

}  // namespace rgnav
