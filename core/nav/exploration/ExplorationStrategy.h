// ExplorationStrategy: what decides where an exploring robot goes next, given the RG map as it
// stands and the robot's pose in it. Two strategies: RG exploration (RgExploration.h, thesis
// chapter 7: complete the current region, then the next untraversed gateway, breadth first) and
// the nearest-frontier baseline (NearestFrontierExploration.h, Yamauchi 1997). Both are driven by
// the Explorer (Explorer.h), in the High-Level Planning module and in the exploration evaluation
// alike.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "core/common/Pose2D.h"
#include "core/nav/exploration/ExplorationConfig.h"
#include "core/nav/planning/PlanningMap.h"

namespace rgnav {

struct ExplorationGoal {
  enum class Kind { Frontier, Gateway, Done };
  Kind kind = Kind::Done;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  // map frame: where to drive
  RegionId region;    // Frontier: the frontier's region; Gateway: the region beyond, if known
  GatewayId gateway;  // Gateway: the gateway to traverse (point: just past its line on the far side,
                      // where the planner plans to; ExplorationTargets.h)
  std::string reason; // one line for logs and the task's progress

  friend bool operator==(const ExplorationGoal&, const ExplorationGoal&) = default;
};

// The driving distance from the robot to a point of the map frame; nullopt: unreachable. The
// caller plans it (RoutePlanner or the PathPlanning module).
using PathLength = std::function<std::optional<double>(const Eigen::Vector2d& goal)>;

struct ExplorationInput {
  const PlanningMap& map;
  Pose2D robot;           // map frame
  RegionId currentRegion; // the kernel's current region (MapSummaryView::current); may be none
};

class ExplorationStrategy {
 public:
  virtual ~ExplorationStrategy() = default;
  virtual std::string name() const = 0;  // "rg" or "frontier"
  // The next goal; Kind::Done once nothing is left to explore.
  virtual ExplorationGoal next(const ExplorationInput& input, const PathLength& pathLength) = 0;
  // The drive to `goal` ended without reaching it (blocked, no path): counted; a goal failed
  // maxGoalFailures times is not chosen again.
  virtual void failed(const ExplorationGoal& goal) = 0;
};

// "rg" or "frontier"; ConfigError otherwise (and for a bad configuration).
std::unique_ptr<ExplorationStrategy> makeExplorationStrategy(const std::string& name, const ExplorationConfig& config);

}  // namespace rgnav
