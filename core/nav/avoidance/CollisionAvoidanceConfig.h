// CollisionAvoidanceConfig: the parameters of the Collision Avoidance (thesis 5.5.3): its laser
// obstacle grid, the swept-footprint check's margin, the candidate chains it builds, when it
// replans, waits and gives up, and the map-less goal seeking that feeds it targets where no map
// exists (BARN, exploration). Read from YAML by CollisionAvoidanceConfigYaml.h
// (config/modules/collisionavoidance.yaml); the robot's footprint and motion limits are the
// robot's, not the module's, and come with the robot's configuration.
#pragma once

#include <cmath>
#include <cstddef>

#include "core/nav/avoidance/LaserObstacleMap.h"

namespace rgnav {

struct CandidateConfig {
  double horizonM = 5.0;             // a chain covers targets up to this far along them
  double turnMaxCurvaturePerM = 3.0; // the turns of the joins (PoseJoins.h TurnShape)
  double turnSharpnessPerM2 = 1.0;       // the path's turns (fast: v <= sqrt(rot. acc. / this))
  double manoeuvreSharpnessPerM2 = 6.0;  // the path again, deviations, fans, after pivots
  double turnMaxSharpnessPerM2 = 40.0;
  double lateralStepM = 0.2;         // deviations: the first targets shifted sideways by k * step
  std::size_t lateralCount = 4;      // ... for k = 1..count on either side
  double fanMaxDeflectionRad = 70.0 * M_PI / 180.0;  // fan: turn by up to +-this, then straight on
  std::size_t fanCount = 9;          // ... this many chains (odd: straight ahead is one)
  double fanLengthM = 1.5;           // length of each fan chain
  double pivotStepRad = M_PI / 4.0;      // standing: turns on the spot by k * step, k = 1..count
  std::size_t pivotCount = 4;        // ... either way (0: no turns on the spot)
};

struct GoalSeekingConfig {
  double replanPeriodS = 0.5;        // plan on the sensed grid this often (and when blocked)
  double inflationMarginM = 0.05;    // the planner's disk: the footprint's inscribed radius + this
  double comfortClearanceM = 0.6;    // paths closer to obstacles than this pay extra
  double clearanceWeight = 4.0;      // extra cost per metre at the smallest clearance
  double targetMinSpacingM = 0.5;
  double targetMaxSpacingM = 1.5;
};

struct CollisionAvoidanceConfig {
  LaserObstacleMapConfig obstacleMap;
  CandidateConfig candidates;
  GoalSeekingConfig goalSeeking;
  double safetyMarginM = 0.05;          // the swept footprint keeps this from obstacles
  double escapeMarginM = 0.01;          // ... for the one chain after a block
  double oncomingSpeedMps = 1.2;        // moving obstacles (people) may come towards the robot this
                                        // fast: chains near them are slow enough to stop before
  double sampleStepM = 0.03;            // poses sampled along chains
  double comfortClearanceM = 0.3;       // chains closer than margin + this pay extra
  double clearanceWeightSPerM = 4.0;    // seconds of cost per metre of clearance below comfort
  double progressWeightSPerM = 2.0;     // seconds of cost per metre left from a chain's end to the goal
  double planningLatencyS = 0.1;        // a new chain starts this far ahead on the current one
  double replanPeriodS = 1.0;           // new targets: replan if the last plan is this old
  double refreshDistanceM = 2.5;        // replan when less than this is left of the chain
  double targetPassedM = 0.5;           // targets closer than this to the chain's start are passed
  double goalToleranceM = 0.1;          // at the last target within this and standing: reached
  double blockedWaitS = 3.0;            // no free chain for this long: blocked
};

// Each throws ConfigError naming the first bad value.
void validate(const CandidateConfig& config);
void validate(const GoalSeekingConfig& config);
void validate(const CollisionAvoidanceConfig& config);

}  // namespace rgnav
