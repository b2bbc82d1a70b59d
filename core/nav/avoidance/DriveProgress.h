// DriveProgress: where a drive of the Collision Avoidance module (idl/CollisionAvoidance.idl) stands:
// its request, its state, the goal and plan it drives, how far along the targets it is, and what
// it has done (chains sent, new plans asked for). Plain values for the module, its client library
// and its checkpoint.
#pragma once

#include <cstdint>
#include <string>

#include "core/nav/planning/PlanRecord.h"

namespace rgnav {

enum class DrivePhase { Idle, Planning, Driving, Waiting, Blocked, Replanning, Reached, Failed };
std::string toString(DrivePhase phase);

struct DriveProgress {
  std::uint64_t request = 0;  // 0: none yet
  DrivePhase phase = DrivePhase::Idle;
  bool hasGoal = false;       // driveTo: `goal` is the drive's (followTargets: targets only)
  PlanGoal goal;
  PlanId plan = 0;            // 0: none (or given targets)
  std::uint32_t targetIndex = 0;
  std::uint32_t targetCount = 0;
  double distanceLeftM = 0.0;
  std::uint64_t chainsSent = 0;
  std::uint32_t replans = 0;
  std::string reason;         // Failed: why

  // Whether the drive still wants the robot to move.
  bool active() const {
    return phase != DrivePhase::Idle && phase != DrivePhase::Reached && phase != DrivePhase::Failed;
  }
};

inline std::string toString(DrivePhase phase) {
  switch (phase) {
    case DrivePhase::Idle: return "idle";
    case DrivePhase::Planning: return "planning";
    case DrivePhase::Driving: return "driving";
    case DrivePhase::Waiting: return "waiting";
    case DrivePhase::Blocked: return "blocked";
    case DrivePhase::Replanning: return "replanning";
    case DrivePhase::Reached: return "reached";
    case DrivePhase::Failed: return "failed";
  }
  return "unknown";
}

}  // namespace rgnav
