// What the ScanMapper serves its followers (see PoseQueries.h).
#include "core/slam/PoseQueries.h"

#include <algorithm>
#include <string>

#include "core/common/Errors.h"
#include "core/slam/CorrectedPoses.h"

namespace rgnav {

std::vector<PoseUpdate> latestPoses(const SlamState& state, DataId firstId, DataId lastId, std::size_t cap) {
  if (firstId == 0 || lastId < firstId) throw InvalidArgumentError("poses wants 1 <= firstId <= lastId");
  const DataId last = state.lastInputId();
  if (firstId > last) throw NotAvailableError("no scan after " + std::to_string(last) + " is mapped yet");
  std::vector<PoseUpdate> out;
  for (DataId id = firstId; id <= std::min(lastId, last) && out.size() < cap; ++id)
    out.push_back(PoseUpdate{id, correctedPose(state, id)});
  return out;
}

std::vector<PoseUpdate> revisedPoses(const SlamState& state, std::uint64_t revision, DataId firstId, DataId lastId,
                                     std::size_t cap) {
  if (firstId == 0 || lastId < firstId) throw InvalidArgumentError("revisedPoses wants 1 <= firstId <= lastId");
  const PoseRevision& kept = keptRevision(state, revision);
  if (lastId >= kept.atScan)
    throw InvalidArgumentError("revision " + std::to_string(revision) + " was made at scan " +
                               std::to_string(kept.atScan) + ": it revises no scan from there on");
  std::vector<PoseUpdate> out;
  for (auto it = firstScanFrom(state, firstId); it != state.scans.end() && it->id <= lastId && out.size() < cap;
       ++it)
    out.push_back(PoseUpdate{it->id, revisedPose(state, it->id, revision)});
  return out;
}

std::vector<PoseRevisionInfo> revisionsAfter(const SlamState& state, std::uint64_t afterRevision) {
  std::vector<PoseRevisionInfo> out;
  for (const PoseRevision& r : state.revisions)
    if (r.number > afterRevision) out.push_back({r.number, r.atScan});
  return out;
}

bool isKeyframe(const SlamState& state, DataId scanId) {
  const auto it = firstScanFrom(state, scanId);
  return it != state.scans.end() && it->id == scanId && it->keyframe != kNoKeyframe;
}

}  // namespace rgnav
