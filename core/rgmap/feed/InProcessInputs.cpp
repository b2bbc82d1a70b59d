// The kernel's inputs in the caller's process (see InProcessInputs.h).
#include "core/rgmap/feed/InProcessInputs.h"

#include <algorithm>
#include <limits>

#include "core/slam/PoseQueries.h"

namespace rgnav {
namespace {

constexpr std::size_t kUncapped = std::numeric_limits<std::size_t>::max();

}  // namespace

InProcessScanMapper::InProcessScanMapper(const SlamConfig& config) : slam_(config) {}

ScanOutcome InProcessScanMapper::add(const LaserScan& scan) {
  const ScanOutcome outcome = slam_.addScan(scan);
  scans_.push_back(scan);
  return outcome;
}

void InProcessScanMapper::finish() {
  slam_.optimize();
  ended_ = true;
}

CorrectedBatch InProcessScanMapper::correctedSince(DataId afterId, std::uint32_t maxCount) {
  CorrectedBatch out;
  out.latestId = slam_.lastInputId();
  out.revision = revision();
  auto it = std::upper_bound(scans_.begin(), scans_.end(), afterId,
                             [](DataId value, const LaserScan& s) { return value < s.id; });
  for (; it != scans_.end() && out.scans.size() < maxCount; ++it)
    out.scans.push_back(CorrectedScan{*it, slam_.correctedPose(it->id), slam_.mappedPose(it->id),
                                      isKeyframe(slam_.state(), it->id)});
  out.endOfData = ended_ && (out.scans.empty() ? afterId : out.scans.back().scan.id) >= out.latestId;
  return out;
}

std::vector<PoseRevisionInfo> InProcessScanMapper::revisionsSince(std::uint64_t afterRevision) {
  slam_.forgetRevisionsUpTo(afterRevision);  // its one follower holds them durably
  return revisionsAfter(slam_.state(), afterRevision);
}

std::vector<PoseUpdate> InProcessScanMapper::revisedPoses(std::uint64_t revision, DataId firstId, DataId lastId) {
  return rgnav::revisedPoses(slam_.state(), revision, firstId, lastId, kUncapped);
}

std::vector<PoseUpdate> InProcessScanMapper::poses(DataId firstId, DataId lastId) {
  return latestPoses(slam_.state(), firstId, lastId, kUncapped);
}

std::uint64_t InProcessScanMapper::revision() { return slam_.state().counters.optimizations; }

InProcessGatewayDetection::InProcessGatewayDetection(const GatewayDetectorConfig& config,
                                                     std::optional<HmmClassifier> classifier)
    : detector_(config, std::move(classifier)) {}

const std::vector<GatewayEvent>& InProcessGatewayDetection::add(const LaserScan& scan) {
  latest_ = detector_.addScan(scan, scan.odometry);
  events_.insert(events_.end(), latest_.begin(), latest_.end());
  return latest_;
}

GatewayEventBatch InProcessGatewayDetection::eventsSince(GatewayEventId afterId, std::uint32_t maxCount) {
  GatewayEventBatch out;
  out.latestId = events_.empty() ? 0 : events_.back().id;
  out.lastScan = detector_.lastScan();
  auto it = std::upper_bound(events_.begin(), events_.end(), afterId,
                             [](GatewayEventId value, const GatewayEvent& e) { return value < e.id; });
  for (; it != events_.end() && out.events.size() < maxCount; ++it) out.events.push_back(*it);
  out.endOfData = ended_ && (out.events.empty() ? afterId : out.events.back().id) >= out.latestId;
  return out;
}

}  // namespace rgnav
