// Frontiers (Yamauchi 1997, "A frontier-based approach for autonomous exploration"): free cells of
// the exploration grid next to an unknown cell (4-neighbourhood), grouped into 8-connected
// clusters; clusters smaller than minCells are dropped. Each frontier belongs to the region that
// holds most of its cells (thesis chapter 7: "a frontier of a region") and offers a viewpoint: a
// free cell at about viewpointBackoffM from the frontier's middle cell, back into the free side,
// from where the laser sees what lies beyond the frontier.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/nav/exploration/ExplorationGrid.h"

namespace rgnav {

struct Frontier {
  RegionId region;
  std::vector<Eigen::Vector2d> cells;  // centres, map frame
  Eigen::Vector2d middle = Eigen::Vector2d::Zero();     // the frontier cell nearest the cells' centroid
  Eigen::Vector2d viewpoint = Eigen::Vector2d::Zero();  // where to drive to see beyond it
  double cellSizeM = 0.0;              // the grid's resolution
  double lengthM() const;              // cells × resolution: the frontier's extent
};

// How far from every line (ExplorationGrid::wallDistanceM) a goal cell keeps: the robot radius, by
// which the route planner inflates walls, plus the distance transform's error (half a cell's
// diagonal), rounded up.
inline double goalClearanceM(const ExplorationGrid& grid, double robotRadiusM) {
  return robotRadiusM + 0.75 * grid.resolutionM();
}

// Largest first. A cluster longer than usefulRangeM (along its main axis) is cut into as many
// equal pieces as it takes for each to be at most that long: one viewpoint sees at most that much
// of it. (The range does not drop frontier cells far from where the robot scanned: the PlanningMap
// holds no scan poses, and the freespace a region holds is what its scans saw, within range.) The viewpoint is a free cell that the free cells join to the middle cell, nearest to the
// point viewpointBackoffM from the middle into the free side, among those goalClearanceM from
// every line (so the route planner, whose walls are inflated by the robot
// radius, accepts it as a goal); where no such cell is near, the one farthest from the lines.
std::vector<Frontier> findFrontiers(const ExplorationGrid& grid, const FrontierConfig& config,
                                    double robotRadiusM = ExplorationConfig{}.robotRadiusM);

}  // namespace rgnav
