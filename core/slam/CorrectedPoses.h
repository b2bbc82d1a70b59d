// Corrected poses by scan ID from a SlamState: keyframes have their estimated pose; a scan that
// was filtered out gets the poses its two surrounding keyframes predict through odometry,
// blended by its ID's position between theirs (after the last keyframe: that keyframe's
// prediction alone). odomToMap is the raw-odometry -> map transform at a scan, thesis 3.3.5:
// the scan is found by ID (the nearest held ID), never by distance, so a place visited twice is
// corrected with the transform of the right visit.
// revisedPose gives the pose a scan had right after an earlier revision (optimisation), from the
// keyframe poses that revision kept (SlamState::revisions).
#pragma once

#include <cstdint>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/common/SensorData.h"
#include "core/slam/SlamState.h"

namespace rgnav {

// The first input scan whose ID is at least scanId (state.scans is in ID order), or the end.
std::vector<ScanRecord>::const_iterator firstScanFrom(const SlamState& state, DataId scanId);

// The kept revision numbered `revision`; NotAvailableError if it is not kept.
const PoseRevision& keptRevision(const SlamState& state, std::uint64_t revision);

// Throws NotAvailableError if no scan with this ID was input.
Pose2D correctedPose(const SlamState& state, DataId scanId);

// The corrected pose scan `scanId` had right after it was input (ScanRecord::mapped). Throws
// NotAvailableError if no scan with this ID was input.
Pose2D mappedPose(const SlamState& state, DataId scanId);

// The corrected pose of scan `scanId` right after revision `revision` (PoseRevision::number).
// Throws InvalidArgumentError unless the scan was input before that revision ran (scanId <
// atScan), NotAvailableError for a scan that was not input or a revision that is not kept.
Pose2D revisedPose(const SlamState& state, DataId scanId, std::uint64_t revision);

// The map pose of an odometry pose taken near scan `scanId`: correctedPose(s) ⊕ odometry(s)^-1 ⊕
// odometryPose, s being the held scan nearest to scanId by ID (the earlier one on a tie).
// Throws NotAvailableError if no scan was input yet.
Pose2D odomToMap(const SlamState& state, DataId scanId, const Pose2D& odometryPose);

}  // namespace rgnav
