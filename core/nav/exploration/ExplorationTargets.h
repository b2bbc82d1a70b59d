// ExplorationTargets: what both exploration strategies (RgExploration.h, NearestFrontierExploration.h)
// choose from and how they check it, so that their comparison measures the order of the goals only:
//   - Open gateways: gateways of the map with a side whose region is not known yet, not
//     neutralised; also those with no region on either side yet (the kernel attaches a door's
//     side only when the robot comes near it, so a door seen from afar is such a hypothesis).
//     Which crossing point lies beyond, on the unexplored side: the unknown side's if sideCrossings
//     says which; else the one farthest from the known side's crossing point; if sideCrossings
//     gives neither, the one with the most unknown cells within 1 m (the other side is the floor
//     the robot saw; a door seen from afar shows only a cone of the room behind it).
//   - A gateway's drive point: the robot must cross the gateway's line for the kernel to open the
//     region beyond (the passage tracker reports a traversal when the robot's path crosses it),
//     and the route planner plans only to points in a region's free cells clear of its walls by
//     the robot radius. The far crossing point lies past the freespace the kernel gives the known
//     region (it cuts a region's freespace at depth_m = 0.3 m beyond its own doors, the crossing
//     points lie 0.5 m off the door line), so it is rarely plannable. The candidates run from
//     the far crossing point back towards the gateway's line (the middle of the two crossing
//     points) in steps of one grid cell, ending one cell before the line; the farthest that the
//     grid shows free and clear of the lines, and that the planner then plans to, is the goal:
//     the robot ends on the far side, the traversal is reported, the kernel opens the new region.
//     A gateway with no such point cannot be traversed by driving to a goal; it is not driven to
//     at all (driving to its near crossing point would leave the robot in front of it for ever).
//   - Frontiers at open gateways belong to the gateway, not to the region: the region's freespace
//     past its door (the kernel's cut) ends in a frontier the robot can never see beyond without
//     traversing. A frontier is at an open gateway when most of its cells lie beyond the
//     gateway's line and within half the gateway's width plus kGatewayFrontierReachM of its middle.
//   - Failures: points (viewpoints) counted within kSameGoalM; a point failed maxGoalFailures
//     times is skipped. A frontier still there while the robot stands at its viewpoint was looked
//     at and stays (glass, a region cut): counted as a failure and skipped this time.
//   - Reachability: the caller's PathLength, asked for the few nearest candidates by straight
//     line first (a plan each), per call only (nothing is kept across map revisions). When no
//     candidate is reachable and the robot's own position is not either, the planner cannot start
//     from where the robot stands (pushed into a wall's inflation): then nothing is dropped and the
//     straight-line distance stands in, so a transient start problem never ends exploration.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "core/nav/exploration/ExplorationStrategy.h"
#include "core/nav/exploration/Frontiers.h"

namespace rgnav {

inline constexpr double kSameGoalM = 0.5;              // failures of points this near are one goal's
inline constexpr double kGatewayFrontierReachM = 1.5;  // the kernel's door cut widens 1 m (RegionModels.h)
inline constexpr std::size_t kNearestByLine = 4;       // candidates planned per batch

struct OpenGateway {
  GatewayId id;
  RegionId known;                                   // the region on its known side; none if neither is
  Eigen::Vector2d near = Eigen::Vector2d::Zero();   // crossing point on the known side
  Eigen::Vector2d far = Eigen::Vector2d::Zero();    // crossing point beyond
  double halfWidthM = 0.0;                          // half the spread of its gateway points
};

// In the order of map.gateways.
std::vector<OpenGateway> openGateways(const PlanningMap& map, const ExplorationGrid& grid, const Eigen::Vector2d& robot);

using PointFailures = std::vector<std::pair<Eigen::Vector2d, std::size_t>>;
void countFailure(PointFailures& failures, const Eigen::Vector2d& point);
std::size_t failuresAt(const PointFailures& failures, const Eigen::Vector2d& point);

// PathLength with the fallback above, for one call of a strategy (a point asked twice is planned once).
class Reachability {
 public:
  Reachability(const PathLength& pathLength, const Eigen::Vector2d& robot) : pathLength_(pathLength), robot_(robot) {}
  std::optional<double> lengthTo(const Eigen::Vector2d& point);
  // The index of the candidate nearest by driving distance, and that distance.
  std::optional<std::pair<std::size_t, double>> nearest(const std::vector<Eigen::Vector2d>& points);

 private:
  bool startPlannable();

  const PathLength& pathLength_;
  Eigen::Vector2d robot_;
  std::optional<bool> startPlannable_;
  std::vector<std::pair<Eigen::Vector2d, std::optional<double>>> asked_;
};

// The gateway's drive point candidates that the grid shows free and clear of the lines, farthest
// beyond the line first (see above); none planned.
std::vector<Eigen::Vector2d> drivePointCandidates(const OpenGateway& gateway, const ExplorationGrid& grid,
                                                  double robotRadiusM);
// The gateway's drive point: the first of its first few candidates that the planner plans to.
std::optional<Eigen::Vector2d> drivePoint(const OpenGateway& gateway, const ExplorationGrid& grid, double robotRadiusM,
                                          Reachability& reach);

// The frontiers worth a goal now: not at open gateways, their viewpoints not failed out, nor the
// one the robot stands at (counted in `failures`).
std::vector<Frontier> candidateFrontiers(const std::vector<Frontier>& frontiers, const std::vector<OpenGateway>& gateways,
                                         const Eigen::Vector2d& robot, PointFailures& failures, std::size_t maxFailures);

}  // namespace rgnav
