// predictedSeconds: the time a plan should take the robot, for the time ratio of the task
// evaluation (issue 29, "rgctl eval tasks": time taken / the planner's predicted time). The motion
// core's prediction (thesis 5.5.3): the chain the Collision Avoidance builds from the plan's
// targets when nothing is in the way, timed with the Low-Level Drive's reference limits
// (TimedTrajectory: the fastest profile from a standstill to a standstill). The chain: a turn on
// the spot towards the first target (the robot stands at the start), then the smooth chain
// through the targets (smoothPolyline with the path's turn shape, CandidateConfig); where that
// cannot be built (a polyline folding back), straights to each target with turns on the spot
// between them. Not predicted: waiting, replanning, and the chains' stops where the avoidance
// cuts a chain short; the ratio measures them.
#pragma once

#include "core/nav/avoidance/CollisionAvoidanceConfig.h"
#include "core/nav/motion/MotionLimits.h"
#include "core/nav/planning/RoutePlanner.h"

namespace rgnav {

// `start`: where the plan starts (map frame, the robot's heading). 0 for a plan without targets.
double predictedSeconds(const Plan& plan, const Pose2D& start, const CandidateConfig& shape, const MotionLimits& limits);

}  // namespace rgnav
