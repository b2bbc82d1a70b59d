// NearestFrontierExploration: the baseline (Yamauchi 1997, "A frontier-based approach for
// autonomous exploration"): drive to the frontier nearest by driving distance, whatever its
// region, until no reachable frontier is left. Same grid, frontiers and viewpoints as RG
// exploration (Frontiers.h), so the comparison measures the order of the goals only.
#pragma once

#include <vector>

#include "core/nav/exploration/ExplorationStrategy.h"

namespace rgnav {

class NearestFrontierExploration : public ExplorationStrategy {
 public:
  explicit NearestFrontierExploration(const ExplorationConfig& config);
  std::string name() const override { return "frontier"; }
  ExplorationGoal next(const ExplorationInput& input, const PathLength& pathLength) override;
  void failed(const ExplorationGoal& goal) override;

 private:
  ExplorationConfig config_;
  std::vector<std::pair<Eigen::Vector2d, std::size_t>> frontierFailures_;
};

}  // namespace rgnav
