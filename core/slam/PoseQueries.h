// What the ScanMapper serves its followers, computed from a SlamState (ScanMapper.idl): the
// latest poses of a range of scans, the poses a range had right after a kept revision, the kept
// revisions after a given one, and whether a scan is a keyframe. The ScanMapper module and the
// in-process mapping chain answer with these, so both serve the same.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/slam/CorrectedScans.h"
#include "core/slam/SlamState.h"

namespace rgnav {

// The corrected poses of scans firstId..lastId, at most `cap`. InvalidArgumentError unless
// 1 <= firstId <= lastId; NotAvailableError if firstId was not input yet.
std::vector<PoseUpdate> latestPoses(const SlamState& state, DataId firstId, DataId lastId, std::size_t cap);

// The poses of the input scans firstId..lastId right after kept revision `revision`, at most
// `cap`. InvalidArgumentError unless 1 <= firstId <= lastId < the revision's atScan;
// NotAvailableError if the revision is not kept.
std::vector<PoseUpdate> revisedPoses(const SlamState& state, std::uint64_t revision, DataId firstId, DataId lastId,
                                     std::size_t cap);

// The kept revisions numbered after `afterRevision`, oldest first.
std::vector<PoseRevisionInfo> revisionsAfter(const SlamState& state, std::uint64_t afterRevision);

// True if the scan was input and became a keyframe.
bool isKeyframe(const SlamState& state, DataId scanId);

}  // namespace rgnav
