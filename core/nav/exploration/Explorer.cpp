// The explorer's loop of goals (Explorer.h).
#include "core/nav/exploration/Explorer.h"

#include "core/common/Errors.h"

namespace rgnav {
namespace {

// Same kind, same gateway, points within two grid cells: driving on to the current goal serves.
bool sameGoal(const ExplorationGoal& a, const ExplorationGoal& b, double cellM) {
  return a.kind == b.kind && a.gateway == b.gateway && (a.point - b.point).norm() <= 2.0 * cellM;
}

}  // namespace

Explorer::Explorer(std::unique_ptr<ExplorationStrategy> strategy, const ExplorationConfig& config)
    : strategy_(std::move(strategy)), config_(config) {
  if (!strategy_) throw InvalidArgumentError("explorer: no exploration strategy");
  validate(config_);
}

ExplorerStep Explorer::update(const ExplorationInput& input, DriveOutcome drive, double now, const PathLength& pathLength) {
  if (done_) return {ExplorerStep::Action::Done, {}};
  const bool driving = goal_ && drive != DriveOutcome::Reached && drive != DriveOutcome::Failed;
  if (driving && now - lastCheck_ < config_.regoalPeriodS) return {ExplorerStep::Action::Keep, *goal_};
  if (goal_ && drive == DriveOutcome::Failed) strategy_->failed(*goal_);
  lastCheck_ = now;
  ExplorationGoal next = strategy_->next(input, pathLength);
  if (next.kind == ExplorationGoal::Kind::Done) {
    done_ = true;
    goal_.reset();
    return {ExplorerStep::Action::Done, next};
  }
  if (driving && sameGoal(next, *goal_, config_.grid.resolutionM)) return {ExplorerStep::Action::Keep, *goal_};
  goal_ = next;
  ++goalsGiven_;
  return {ExplorerStep::Action::DriveTo, next};
}

}  // namespace rgnav
