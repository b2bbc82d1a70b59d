// CrowdRun: drives the crowd evaluation's goals one after the other through the Collision
// Avoidance module (driveTo: the PathPlanning module plans, the CAM drives) and judges each: reached
// when the CAM reports it reached and the robot's TRUE pose is within `toleranceM` of the goal;
// not reached when the CAM gives up (failed) or the goal takes longer than `goalTimeoutS`. The CAM
// may be restarted meanwhile (the motion fault test kills it): a status call that fails is asked
// again, and a CAM that answers with another request (it lost the drive) gets the same driveTo
// request again, which it deduplicates. Distances and speeds come from the true poses, and so does
// each goal's driven path (a point whenever the robot moved more than 5 cm, and where it ended).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "clientlibs/common/ClientSettings.h"

namespace rgnav {

struct CrowdRunOptions {
  double toleranceM = 0.3;
  double goalTimeoutS = 120.0;
  bool verbose = true;  // a line per goal on stdout
};

struct GoalOutcome {
  Eigen::Vector2d goal;
  bool reached = false;
  std::string finalState;  // the CAM's last state ("reached", "failed", ...; "timeout")
  double seconds = 0.0;    // wall time from driveTo to the end
  double distanceM = 0.0;  // true distance driven
  double finalErrorM = 0.0;
  unsigned replans = 0;
  std::string reason;      // the CAM's last reason (why it failed or waits)
  std::vector<Eigen::Vector2d> path;  // true positions from the start to the end of the drive
};

struct CrowdOutcome {
  std::vector<GoalOutcome> goals;
  std::size_t reached() const;
  double meanSpeedMps() const;  // true distance over time, over the reached goals
};

CrowdOutcome driveGoals(const ClientSettings& settings, const std::vector<Eigen::Vector2d>& goals,
                        const CrowdRunOptions& options);

}  // namespace rgnav
