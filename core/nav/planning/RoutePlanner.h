// RoutePlanner: plans with an RG map (thesis 5.4): a global route on the RG graph joined with paths
// inside the regions it passes, cut into intermediate target poses for the collision avoidance
// (thesis 5.5.3: 0.5 to 2 m apart), each with the region it lies in.
//   - Region grids (RegionGrid.h): a region's line map rendered into a grid at `gridResolutionM`
//     within its freespace, walls inflated by the robot radius, built once per region and map
//     revision. A start or crossing point just off the free cells moves onto the nearest one (a
//     start not across a wall line; a crossing point, which the robot drove through, may: the
//     line map may close a door's frame a little).
//   - Route: A* over the RG graph's crossing points. Deliberate differences from the thesis (whose
//     region edges cost their learned cost, initially the Euclidean length): a region edge costs
//     at least the length of the region path between its crossing points, and the start and goal
//     join the graph with their region path lengths, so that a route never relies on a straight
//     line through walls; where two regions' free cells overlap, the route may pass there
//     (RegionOverlaps.h); and a gateway that is not in the RG graph yet because the region on one
//     of its sides is unknown (the detector saw it, the kernel has not placed it between two
//     regions) joins the regions in whose free cells its crossing points lie.
//   - Region paths: the framed-quadtree planner (FramedQuadtreePlanner.h) in each region between
//     its entry and exit points; a gateway is crossed on the straight line between its two
//     crossing points, through the middle of a door. Ours: each route node (crossing point,
//     passage end) gets the planner's field to it once per map revision, so a query costs its
//     links by lookups and reads only the chosen paths off the fields; only start and goal in one
//     region are planned directly.
// Goals: a point of the map frame, a region (by ID or name: its free point nearest the freespace
// centroid), or a named object (a free pose in front of it, facing it).
// Starts: the start lies in the regions in whose free cells it lies and from where it leads on,
// i.e. whose planner reaches from it a route node of the region (a crossing point, an overlap
// transfer, a passage end) or the goal. A start in no such place (outside every region, or in a
// pocket of a region's free cells cut off from the rest by the inflation, where a robot pushed to
// a wall corner can stand: a sliver of a region's freespace beyond its walls' ends) is placed on
// the nearest free cell within `startSnapM` that leads on, in any region, not across a wall line.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/nav/planning/FramedQuadtreePlanner.h"
#include "core/nav/planning/PlanningMap.h"

namespace rgnav {

struct RoutePlannerConfig {
  double robotRadiusM = 0.25;
  double gridResolutionM = 0.05;
  double startSnapM = 1.0;          // a start this close to a region's free cells is placed in it
  double crossingSnapM = 0.5;       // a crossing point in a blocked cell moves to the nearest free one
  double overlapSampleM = 0.15;     // regions' free cells are compared on this lattice (RegionOverlaps.h)
  double overlapMinAreaM2 = 0.25;   // smaller overlaps are no transfer
  double targetMinSpacingM = 0.5;   // intermediate targets (thesis 5.5.3)
  double targetMaxSpacingM = 2.0;
  FramedQuadtreePlannerConfig region{.wallCostDistanceM = 0.5, .wallCostWeight = 1.0};
};

// Throws ConfigError naming the first value out of range.
void validate(const RoutePlannerConfig& config);

struct PlanGoal {
  enum class Kind { Point, Region, RegionName, Object };
  Kind kind = Kind::Point;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  // Kind::Point: map frame
  RegionId region;                                  // Kind::Region
  std::string name;                                 // Kind::RegionName, Kind::Object

  static PlanGoal at(const Eigen::Vector2d& p) { return {Kind::Point, p, {}, {}}; }
  static PlanGoal inRegion(RegionId r) { return {Kind::Region, Eigen::Vector2d::Zero(), r, {}}; }
  static PlanGoal inRegionNamed(std::string n) { return {Kind::RegionName, Eigen::Vector2d::Zero(), {}, std::move(n)}; }
  static PlanGoal atObject(std::string n) { return {Kind::Object, Eigen::Vector2d::Zero(), {}, std::move(n)}; }
};

struct TargetPose {
  Pose2D pose;      // map frame; theta: the direction of travel (at the goal: of the last leg,
                    // or facing the object for an object goal)
  RegionId region;  // the region the target lies in

  friend bool operator==(const TargetPose&, const TargetPose&) = default;
};

struct Plan {
  std::vector<TargetPose> targets;    // driving order, 0.5 to 2 m apart; the goal last
  std::vector<GraphNodeView> route;   // crossing points passed, driving order (in pairs per gateway;
                                      // for a gateway not in the RG graph yet, `side` is the index
                                      // of the crossing point among the gateway's)
  std::vector<Eigen::Vector2d> path;  // the whole path as a polyline, map frame, start first
  double lengthM = 0.0;               // length of `path`: the predicted driving distance
  RegionId startRegion, goalRegion;
  RgMapEventId mapRevision = 0;       // the map it was planned on
};

class RoutePlanner {
 public:
  // Throws ConfigError for a bad configuration.
  explicit RoutePlanner(const RoutePlannerConfig& config = {});

  // Replaces the map; region grids of an unchanged revision are kept for the regions whose summary
  // is unchanged (scans stacked into the current region are no new revision).
  void setMap(PlanningMap map);
  const PlanningMap& map() const { return map_; }

  // Plans from `start` (map frame) to `goal`. Throws NoPathError (PlanningErrors.h) naming why:
  // a start outside every region or cut off in one (no free cell that leads on within
  // startSnapM), a goal outside every region or inside an
  // obstacle, an unknown region or name, no route between the regions, no path inside a region.
  // InvalidArgumentError for a non-finite start or goal point.
  Plan plan(const Pose2D& start, const PlanGoal& goal) const;

  // The regions in whose planning grid `point` (map frame) lies in a free cell: where the robot
  // can stand in the map.
  std::vector<RegionId> regionsAt(const Eigen::Vector2d& point) const;

 private:
  struct RegionEntry;
  struct Ends;
  // Ways between regions beyond the RG graph's gateway edges, each joining some of its ends at
  // their straight-line distance: an overlap of two regions (both ends at one point), or a
  // gateway the RG graph does not hold yet (a side's region unknown), its crossing points placed
  // in the regions whose free cells hold them and two of them joined where the straight line
  // between them stays on free cells of the map (a door's: through its middle). Nobody has
  // driven these, unlike the RG graph's gateway edges, so they are checked.
  struct PassageEnd {
    Eigen::Vector2d position;  // map frame
    RegionId region;
    std::size_t crossing = 0;  // a gateway's: the index of its crossing point
  };
  struct Passage {
    GatewayId gateway;  // none: an overlap
    std::vector<PassageEnd> ends;
    std::vector<std::pair<std::size_t, std::size_t>> links;  // the ends joined, by index
  };
  std::vector<Passage> findPassages() const;
  // The route search's nodes and links of the map now (RoutePlanner.cpp), found on first use after
  // a map change.
  struct RouteGraph;
  const RouteGraph& routeGraph() const;
  // The middle of a door's gateway points; none for a gateway that is no door.
  std::optional<Eigen::Vector2d> doorMiddle(GatewayId gateway) const;
  // Whether two ends of a gateway passage may be joined (see above); `middle`: a door's.
  bool passageFree(const PassageEnd& a, const PassageEnd& b, const std::optional<Eigen::Vector2d>& middle) const;
  // The region's grid and planner, built on first use. Throws NoPathError for an unknown region.
  RegionEntry& entry(RegionId region) const;
  // A route node's point placed on a free cell of the region (a crossing point moves at most
  // crossingSnapM, over wall lines; none if no free cell is that near). Cached per region entry.
  std::optional<Eigen::Vector2d> placed(RegionEntry& region, std::size_t node) const;
  // Whether a component of the region's free cells (none: off them) holds one of the region's
  // route nodes or the goal: a start there leads on.
  bool leadsOn(RegionId region, std::optional<std::int32_t> component, const Ends& goal) const;
  Ends startOf(const Pose2D& start, const Ends& goal) const;
  Ends goalOf(const PlanGoal& goal, const Eigen::Vector2d& start) const;

  RoutePlannerConfig config_;
  PlanningMap map_;
  mutable std::map<RegionId, std::shared_ptr<RegionEntry>> regions_;  // built on first use
  mutable std::shared_ptr<const RouteGraph> routeGraph_;
};

}  // namespace rgnav
