// Corrected poses by scan ID from a SlamState: keyframes have their estimated pose; a scan that
// was filtered out gets the poses its two surrounding keyframes predict through odometry,
// blended by its ID's position between theirs (after the last keyframe: that keyframe's
// prediction alone). odomToMap is the raw-odometry -> map transform at a scan, thesis 3.3.5:
// the scan is found by ID (the nearest held ID), never by distance, so a place visited twice is
// corrected with the transform of the right visit.
#pragma once

#include "core/common/Pose2D.h"
#include "core/common/SensorData.h"
#include "core/slam/SlamState.h"

namespace rgnav {

// Throws NotAvailableError if no scan with this ID was input.
Pose2D correctedPose(const SlamState& state, DataId scanId);

// The map pose of an odometry pose taken near scan `scanId`: correctedPose(s) ⊕ odometry(s)^-1 ⊕
// odometryPose, s being the held scan nearest to scanId by ID (the earlier one on a tie).
// Throws NotAvailableError if no scan was input yet.
Pose2D odomToMap(const SlamState& state, DataId scanId, const Pose2D& odometryPose);

}  // namespace rgnav
