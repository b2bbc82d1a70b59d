// DriveCheckpoint: the Collision Avoidance module's drive as it survives a restart (DESIGN.md,
// "State survives"): the request and progress (DriveProgress.h) and the drive's target poses in
// the map frame, written atomically to the module's state directory whenever a drive starts,
// gets a new plan, or ends. A restarted module that finds an active drive resumes it toward the
// same goal: a drive to a goal is planned again from where the robot stands, given targets are
// driven on from the target reached last. The text is JSON ({"format": "rgnav-drive", "version":
// 1, ...}) with every number written so that it reads back to exactly the same double.
#pragma once

#include <string>
#include <vector>

#include "core/nav/avoidance/DriveProgress.h"

namespace rgnav {

struct DriveRecord {
  DriveProgress progress;
  std::vector<TargetPose> targets;  // map frame, driving order, the goal last
};

std::string serializeDrive(const DriveRecord& drive);
// Throws FormatError naming `source` for a text that is not such a checkpoint.
DriveRecord deserializeDrive(const std::string& text, const std::string& source);

}  // namespace rgnav
