// ExplorationConfig: the parameters of exploration (thesis chapter 7's region-by-region
// exploration and the nearest-frontier baseline): the grid the frontiers are found on, what counts
// as a frontier worth driving to, and when the explorer gives a goal up. The High-Level Planning
// module reads them from config/modules/highlevelplanning.yaml (ExplorationConfigYaml.h).
#pragma once

#include <cstddef>

namespace rgnav {

struct ExplorationGridConfig {
  double resolutionM = 0.1;      // map-frame cells the regions' freespace is sampled on
  double wallClearanceM = 0.2;   // a cell this near a line of the map is wall, never frontier
};

struct FrontierConfig {
  std::size_t minCells = 5;      // smaller frontier clusters are noise, not unexplored space
  double usefulRangeM = 6.0;     // the laser sees a frontier from at most this far
  double viewpointBackoffM = 0.6;  // the goal lies this far from the frontier on the free side
};

struct ExplorationConfig {
  ExplorationGridConfig grid;
  FrontierConfig frontier;
  double robotRadiusM = 0.25;
  std::size_t maxGoalFailures = 2;  // a goal (frontier or gateway) failed this often is dropped
  double regoalPeriodS = 3.0;       // while driving, the goal is checked against the newest map this often
};

// Throws ConfigError naming the first value out of range.
void validate(const ExplorationConfig& config);

}  // namespace rgnav
