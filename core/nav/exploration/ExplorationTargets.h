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
//     points) in steps of one grid cell, ending one cell past the line; of those the grid shows
//     free and the robot radius clear of the lines, the first of at most three that the planner
//     plans to is the goal: the robot ends on the far side (the collision avoidance stops within
//     0.1 m of a goal; the kernel's cut leaves 0.2 to 0.3 m past a door to aim at), the traversal
//     is reported, the kernel opens the new region.
//     A gateway with candidates none of which plans cannot be traversed by driving to a goal; it is
//     not driven to at all (driving to its near crossing point would leave the robot in front of
//     it for ever). A gateway with no candidate yet (the freespace does not reach past its line:
//     the robot saw the door at a slant) is no target yet.
//   - Frontiers at open gateways belong to the gateway, not to the region: the region's freespace
//     past its door (the kernel's cut) ends in a frontier the robot can never see beyond without
//     traversing. A frontier is at an open gateway when most of its cells lie beyond the
//     gateway's line and within half the gateway's width plus kGatewayFrontierReachM of its middle,
//     and the gateway has drive point candidates (else the frontier leads the robot to look
//     through the door, which gives it some).
//   - Failures: points (viewpoints) counted within kSameGoalM; a point failed maxGoalFailures
//     times is skipped. A frontier still there while the robot stands at its viewpoint was looked
//     at and stays (glass, a region cut): counted as a failure and skipped this time.
//   - Reachability: the caller's PathLength, asked for the few nearest candidates by straight
//     line first (a plan each), within one call only (nothing is kept across map revisions). The
//     first time a candidate does not plan, the robot's own position is asked: if that does not
//     plan either, the planner cannot start from where the robot stands (pushed into a wall's
//     inflation), and the straight-line distance stands in for every candidate of the call, so a
//     transient start problem drops nothing and never ends exploration.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
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
  std::vector<Eigen::Vector2d> drivePoints;         // its drive point candidates, farthest first
};

// In the order of map.gateways; drive point candidates: those the grid shows free and the robot
// radius clear of the lines (the planner decides on the ones this leaves: at a door they lie close
// to its jambs).
std::vector<OpenGateway> openGateways(const PlanningMap& map, const ExplorationGrid& grid, const Eigen::Vector2d& robot,
                                      double robotRadiusM);

using PointFailures = std::vector<std::pair<Eigen::Vector2d, std::size_t>>;
void countFailure(PointFailures& failures, const Eigen::Vector2d& point);
std::size_t failuresAt(const PointFailures& failures, const Eigen::Vector2d& point);

// PathLength with the fallback above, for one call of a strategy (a point asked twice is planned once).
class Reachability {
 public:
  Reachability(const PathLength& pathLength, const Eigen::Vector2d& robot) : pathLength_(pathLength), robot_(robot) {}
  std::optional<double> lengthTo(const Eigen::Vector2d& point);
  struct Nearest {
    std::size_t index = 0;
    Eigen::Vector2d goal = Eigen::Vector2d::Zero();
    double lengthM = 0.0;
  };
  // The candidate nearest by driving distance: candidates ranked by the straight line to `points`,
  // candidate i planned to goalOf(i) (to points[i] without it; none: not reachable).
  std::optional<Nearest> nearest(const std::vector<Eigen::Vector2d>& points,
                                 const std::function<std::optional<Eigen::Vector2d>(std::size_t)>& goalOf = nullptr);

 private:
  bool startPlannable();

  const PathLength& pathLength_;
  Eigen::Vector2d robot_;
  std::optional<bool> startPlannable_;
  std::vector<std::pair<Eigen::Vector2d, std::optional<double>>> asked_;
};

// The gateway's drive point: the first of its first few candidates that the planner plans to.
std::optional<Eigen::Vector2d> drivePoint(const OpenGateway& gateway, Reachability& reach);

// What a strategy chooses from on the map now: its grid, its open gateways, and the frontiers worth
// a goal (not at open gateways, their viewpoints not failed out, nor the one the robot stands
// at, which is counted in `failures`).
struct Survey {
  ExplorationGrid grid;
  std::vector<OpenGateway> open;
  std::vector<Frontier> frontiers;
};
Survey survey(const ExplorationInput& input, const ExplorationConfig& config, PointFailures& failures);

}  // namespace rgnav
