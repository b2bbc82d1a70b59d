// ChainCandidates: the chains of trajectory segments the Collision Avoidance chooses among
// (thesis 5.5.3: "generate consecutive trajectory segments given the target poses"): from the
// start state, the smooth chain through the next targets (pose joins of core/nav/motion), the same
// with the first one to three targets shifted sideways by a few steps either way (deviations
// around an obstacle on the path that join back to it), and a fan of turns by different angles, each followed by a straight (ways out when
// the targets are blocked). All are curvature-continuous: straights and clothoid-arc-clothoid
// turns, 0 curvature at both ends (the start state's curvature is not continued). A robot that
// stands may also first turn on the spot (towards the first target, or by steps either way):
// the pivot is an arc of kPivotCurvature, a millimetre-radius circle, which the velocity profile
// drives at the rotational limits with next to no translation (the primitives have no other way
// to say "turn in place").
// Every chain ends where the robot is to stand: the caller times it to a standstill.
#pragma once

#include <span>
#include <vector>

#include "core/nav/avoidance/CollisionAvoidanceConfig.h"
#include "core/nav/motion/TrajectoryChain.h"

namespace rgnav {

// The curvature of a turn on the spot, 1/m.
constexpr double kPivotCurvature = 1000.0;

// Turning on the spot at `at` by `angle` (positive: left).
TrajectorySegment pivot(const Pose2D& at, double angle);

struct ChainStart {
  Pose2D pose;
  double speed = 0.0;      // m/s
  double curvature = 0.0;  // 1/m
  bool standing = false;   // the robot stands (it may turn on the spot)
};

struct Candidate {
  enum class Kind { Path, Deviation, Fan, Pivot };
  Kind kind = Kind::Path;
  TrajectoryChain chain;
};

// `targets`: the targets still ahead (the next first), at least one.
std::vector<Candidate> candidateChains(const ChainStart& start, std::span<const Pose2D> targets,
                                       const CandidateConfig& config);

// The part of `chain` between arc lengths `from` and `to` (clamped to the chain; empty if not
// from < to).
TrajectoryChain sliceChain(const TrajectoryChain& chain, double from, double to);

}  // namespace rgnav
