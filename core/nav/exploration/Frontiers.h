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
  double lengthM() const;              // cells × resolution: the frontier's extent
};

// Largest first.
std::vector<Frontier> findFrontiers(const ExplorationGrid& grid, const FrontierConfig& config);

}  // namespace rgnav
