// Explorer: runs an exploration strategy against a drive that the caller carries out (the High-
// Level Planning module through PathPlanning → CollisionAvoidance → LowLevelDrive; the exploration
// evaluation in process). On every call it gets the newest map, the robot's pose and how the drive
// to its last goal stands, and answers: keep driving, drive to a new goal, or done.
//   - No goal yet, goal reached, goal failed (counted with the strategy), no drive to the goal
//     (None after a DriveTo: the caller lost it): the strategy's next goal.
//   - While driving, every regoalPeriodS (simulated or wall seconds, the caller's clock): the
//     strategy is asked again on the newest map; a different goal replaces the current one (its
//     frontier was seen meanwhile, or a nearer one appeared). A goal is not replaced by an equal
//     one (same kind, gateway, and point within 2 grid cells), so a drive is not restarted for
//     nothing.
//   - Done: once the strategy says so.
//   - A map without regions (the kernel has not made its first region yet): Keep, the strategy is
//     not asked (it would find nothing to explore and say Done).
#pragma once

#include <memory>
#include <optional>

#include "core/nav/exploration/ExplorationStrategy.h"

namespace rgnav {

enum class DriveOutcome { None, Driving, Reached, Failed };

struct ExplorerStep {
  enum class Action { Keep, DriveTo, Done };
  Action action = Action::Keep;
  ExplorationGoal goal;  // DriveTo: the new goal; Keep: the current one
};

class Explorer {
 public:
  // Throws ConfigError for a bad configuration.
  Explorer(std::unique_ptr<ExplorationStrategy> strategy, const ExplorationConfig& config);

  // `now`: seconds on the caller's clock; `drive`: the state of the drive to the goal last
  // answered with DriveTo (None before the first).
  ExplorerStep update(const ExplorationInput& input, DriveOutcome drive, double now, const PathLength& pathLength);

  const std::optional<ExplorationGoal>& goal() const { return goal_; }
  std::size_t goalsGiven() const { return goalsGiven_; }
  bool done() const { return done_; }
  const ExplorationStrategy& strategy() const { return *strategy_; }

 private:
  std::unique_ptr<ExplorationStrategy> strategy_;
  ExplorationConfig config_;
  std::optional<ExplorationGoal> goal_;
  double lastCheck_ = 0.0;
  std::size_t goalsGiven_ = 0;
  bool done_ = false;
};

}  // namespace rgnav
