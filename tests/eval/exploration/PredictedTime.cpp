// The predicted time of a plan; see PredictedTime.h.
#include "tests/eval/exploration/PredictedTime.h"

#include <cmath>

#include "core/nav/avoidance/ChainCandidates.h"
#include "core/nav/motion/PoseJoins.h"
#include "core/nav/motion/TimedTrajectory.h"

namespace rgnav {
namespace {

constexpr double kAligned = 1e-3;  // rad: no turn on the spot below this

// Turns the chain's end on the spot towards `target`.
void face(TrajectoryChain& chain, Pose2D& at, const Pose2D& target) {
  const double angle = normalizeAngle(std::atan2(target.y - at.y, target.x - at.x) - at.theta);
  if (std::abs(angle) < kAligned) return;
  const TrajectorySegment turn = pivot(at, angle);
  chain.append(turn);
  at = turn.end();
}

}  // namespace

double predictedSeconds(const Plan& plan, const Pose2D& start, const CandidateConfig& shape, const MotionLimits& limits) {
  if (plan.targets.empty()) return 0.0;
  std::vector<Pose2D> targets;
  for (const TargetPose& t : plan.targets) targets.push_back(t.pose);
  TrajectoryChain chain;
  Pose2D at = start;
  face(chain, at, targets.front());
  const TurnShape turns{shape.turnMaxCurvaturePerM, shape.turnSharpnessPerM2, shape.turnMaxSharpnessPerM2};
  if (const std::optional<TrajectoryChain> smooth = smoothPolyline(at, targets, turns)) {
    for (const TrajectorySegment& segment : smooth->segments()) chain.append(segment);
  } else {
    for (const Pose2D& target : targets) {
      face(chain, at, target);
      const double length = std::hypot(target.x - at.x, target.y - at.y);
      if (length <= 0.0) continue;
      const TrajectorySegment straight{at, length, 0.0, 0.0};
      chain.append(straight);
      at = straight.end();
    }
  }
  if (chain.empty()) return 0.0;
  return TimedTrajectory(chain, limits).duration();
}

}  // namespace rgnav
