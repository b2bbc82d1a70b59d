// RobotPose: where the High-Level Planning module takes the robot's pose in the map frame from
// (exploration's start and goals, where a naming question was asked). Two sources, one per set:
//   - scanmapper (while mapping): the ScanMapper's corrected pose of its newest scan. While the
//     ScanMapper maps, its frame IS the map frame (the RG Mapping Kernel's regions are placed by
//     its corrected poses), so no conversion is needed; the pose is as old as the newest scan (the
//     ScanMapper keeps scans some centimetres apart), which is close enough to choose goals by.
//   - localization (a known map, no mapping): the Localization module's estimate (its map frame
//     is the saved map's).
// How the two are reconciled: a set runs one of them. While mapping, the Localization module, if
// it runs, is started at the first scan's odometry in the ScanMapper's frame and tracks in it, so
// both name the same frame and the ScanMapper's is used (it defines the map); in a saved map
// without mapping there is no ScanMapper and the Localization module's pose is the one. Deliberate
// difference from the thesis, which leaves this to the modules' wiring: the choice is explicit
// (--pose-source), so a set cannot mix two frames unnoticed. No source reads the simulator's
// ground truth.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "clientlibs/common/ClientSettings.h"
#include "core/common/Pose2D.h"

namespace rgnav {

class RobotPose {
 public:
  virtual ~RobotPose() = default;
  // The newest pose; none while the source has none yet (no scan mapped, not localized). Throws
  // what the source's client throws when the module does not answer.
  virtual std::optional<Pose2D> pose() = 0;
};

// "scanmapper" or "localization" (ConfigError otherwise), reached under `objectName` (empty: the
// source module's usual name).
std::unique_ptr<RobotPose> makeRobotPose(const std::string& source, const ClientSettings& settings,
                                         const std::string& objectName = {});

}  // namespace rgnav
