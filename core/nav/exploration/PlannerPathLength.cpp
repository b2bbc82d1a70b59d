// Planned path lengths for exploration (PlannerPathLength.h).
#include "core/nav/exploration/PlannerPathLength.h"

#include "core/nav/grid/PlanningErrors.h"

namespace rgnav {

PathLength plannerPathLength(const RoutePlanner& planner, const Pose2D& robot) {
  return [&planner, robot](const Eigen::Vector2d& goal) -> std::optional<double> {
    try {
      return planner.plan(robot, PlanGoal::at(goal)).lengthM;
    } catch (const NoPathError&) {
      return std::nullopt;
    } catch (const StartBlockedError&) {  // a region planner's: the robot or the point in no free cell
      return std::nullopt;
    } catch (const GoalBlockedError&) {
      return std::nullopt;
    }
  };
}

}  // namespace rgnav
