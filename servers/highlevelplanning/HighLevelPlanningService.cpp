// The High-Level Planning module's task loop, naming dialog and checkpoint (see
// HighLevelPlanningService.h).
#include "servers/highlevelplanning/HighLevelPlanningService.h"

#include <cstdio>
#include <iostream>

#include "core/common/AtomicFile.h"
#include "core/nav/exploration/PlannerPathLength.h"

namespace rgnav {
namespace {

HighLevelPlanningState loadCheckpoint(const std::string& file) {
  const std::optional<std::string> saved = file.empty() ? std::nullopt : readCheckpoint(file);
  return saved ? deserializeTasks(*saved, file) : HighLevelPlanningState{};
}

DriveOutcome outcomeOf(const DriveProgress& drive) {
  switch (drive.phase) {
    case DrivePhase::Reached: return DriveOutcome::Reached;
    case DrivePhase::Failed:
    case DrivePhase::Idle: return DriveOutcome::Failed;
    default: return DriveOutcome::Driving;
  }
}

}  // namespace

HighLevelPlanningService::HighLevelPlanningService(const HighLevelPlanningConfig& config, const ClientSettings& settings,
                                                   HighLevelPlanningServiceOptions options, ModuleHealth& health)
    : config_(config),
      options_(std::move(options)),
      health_(health),
      kernel_(settings, options_.kernelObject),
      avoidance_(settings, options_.avoidanceObject),
      pose_(makeRobotPose(options_.poseSource, settings, options_.poseObject)),
      cache_(kernel_),
      planner_(config.routePlanner),
      namer_(settings, options_.kernelObject),
      state_(loadCheckpoint(options_.checkpointFile)),
      retry_(health),
      follower_(
          health, "avoidance", [this] { return step(); }, [this] { return blockActiveTask(); },
          std::chrono::milliseconds(static_cast<long>(config.pollPeriodS * 1000))) {
  validate(config_);
  makeExplorationStrategy(options_.strategy, config_.exploration);  // ConfigError now, not at the first exploration
  const Task* active = state_.queue.active();
  health_.set("resumed_task", active ? active->id : 0);
}

// ---- servant side ----------------------------------------------------------------------------

template <class Add>
Task HighLevelPlanningService::queue(std::uint64_t request, Add&& add) {
  if (request == 0) throw InvalidArgumentError("request ID 0");
  std::lock_guard lock(mutex_);
  const TaskId next = state_.queue.nextId();
  const Task task = add();
  if (task.id == next) health_.add("tasks");
  checkpoint();
  return task;
}

Task HighLevelPlanningService::goTo(std::uint64_t request, const PlanGoal& goal) {
  return queue(request, [&] { return state_.queue.goTo(goal, request); });
}

Task HighLevelPlanningService::explore(std::uint64_t request) {
  return queue(request, [&] { return state_.queue.explore(request); });
}

Task HighLevelPlanningService::stopAll(std::uint64_t request) {
  if (request == 0) throw InvalidArgumentError("request ID 0");
  std::lock_guard lock(mutex_);
  if (const Task* known = state_.queue.byRequest(request)) return *known;
  const Task task = state_.queue.stop(request);
  cancelOwed_ = true;
  health_.add("tasks");
  checkpoint();
  return task;
}

Task HighLevelPlanningService::cancel(std::uint64_t request, TaskId id) {
  if (request == 0) throw InvalidArgumentError("request ID 0");
  std::lock_guard lock(mutex_);
  if (const std::uint64_t* answered = state_.requests.find(request)) {
    if (const Task* task = state_.queue.find(*answered)) return *task;
    throw NotAvailableError("task " + std::to_string(*answered) + " is no longer kept");
  }
  TaskId target = id;
  if (target == 0) {
    const Task* active = state_.queue.active();
    if (!active) throw NotAvailableError("no task is active");
    target = active->id;
  }
  const Task* before = state_.queue.find(target);
  const bool wasActive = before && before->state == TaskState::Active;
  const bool wasWaiting = before && !ended(before->state);
  const Task task = state_.queue.cancel(target, "cancelled on request");
  if (wasActive) cancelOwed_ = true;
  if (wasWaiting) health_.add("cancelled");
  state_.requests.add(request, target);
  checkpoint();
  return task;
}

Task HighLevelPlanningService::task(TaskId id) {
  std::lock_guard lock(mutex_);
  const Task* task = state_.queue.find(id);
  if (!task) throw NotAvailableError("task " + std::to_string(id) + " is not kept (the next task is " +
                                     std::to_string(state_.queue.nextId()) + ")");
  return *task;
}

std::vector<Task> HighLevelPlanningService::tasks() {
  std::lock_guard lock(mutex_);
  return state_.queue.tasks();
}

std::vector<NamingQuestion> HighLevelPlanningService::questions() {
  std::lock_guard lock(mutex_);
  return state_.dialog.waiting();
}

TaskId HighLevelPlanningService::nextTaskId() {
  std::lock_guard lock(mutex_);
  return state_.queue.nextId();
}

void HighLevelPlanningService::answer(std::uint64_t request, QuestionId question, const std::string& name) {
  if (request == 0) throw InvalidArgumentError("request ID 0");
  if (name.empty()) throw InvalidArgumentError("an empty name");
  std::lock_guard naming(namingMutex_);
  RegionId region;
  {
    std::lock_guard lock(mutex_);
    if (state_.requests.find(request)) return;
    region = state_.dialog.question(question).region;
  }
  namer_.nameRegion(region, name);
  std::lock_guard lock(mutex_);
  state_.dialog.answered(question);
  state_.requests.add(request, question);
  health_.add("answers");
  checkpoint();
}

void HighLevelPlanningService::checkpoint() {
  if (options_.checkpointFile.empty() || !retry_.due()) return;
  try {
    writeFileAtomically(options_.checkpointFile, serializeTasks(state_));
    retry_.succeeded();
  } catch (const FileError& e) {
    retry_.failed(e.what());
  }
}

// ---- the task loop ---------------------------------------------------------------------------

double HighLevelPlanningService::now() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

bool HighLevelPlanningService::step() {
  {
    std::lock_guard lock(mutex_);
    if (retry_.failing() && retry_.due()) checkpoint();
  }
  pollKernel();
  runTask();
  return false;  // the loop runs every pollPeriodS
}

std::optional<Pose2D> HighLevelPlanningService::robotPose() {
  try {
    std::optional<Pose2D> pose = pose_->pose();
    health_.clearError("pose");
    return pose;
  } catch (const Error& e) {
    health_.setError("pose", e.what());
    return std::nullopt;
  }
}

void HighLevelPlanningService::pollKernel() {
  try {
    summary_ = kernel_.summary();
    if (!regionsRevision_ || *regionsRevision_ != summary_.lastEvent || regionsCurrent_ != summary_.current) {
      regions_ = kernel_.regions();
      regionsRevision_ = summary_.lastEvent;
      regionsCurrent_ = summary_.current;
    }
    health_.clearError("kernel");
  } catch (const Error& e) {
    health_.setError("kernel", e.what());
    return;
  }
  bool ask = false;
  {
    std::lock_guard lock(mutex_);
    ask = state_.dialog.wouldAsk(summary_.current, regions_);
  }
  // Where the question is asked: the robot's pose, or without one the region frame's origin.
  Eigen::Vector2d where = Eigen::Vector2d::Zero();
  for (const RegionSummaryView& r : regions_)
    if (r.id == summary_.current) where = {r.frame.x, r.frame.y};
  if (const std::optional<Pose2D> robot = ask ? robotPose() : std::nullopt) where = {robot->x, robot->y};
  std::lock_guard lock(mutex_);
  const std::vector<NamingQuestion> before = state_.dialog.waiting();
  if (const auto asked = state_.dialog.observe(summary_.current, where, regions_)) {
    health_.add("questions");
    std::cerr << "high-level planning: question " << asked->id << ": " << asked->text << std::endl;
  }
  if (state_.dialog.waiting() != before) checkpoint();
}

void HighLevelPlanningService::runTask() {
  bool cancelOwed = false;
  {
    std::lock_guard lock(mutex_);
    cancelOwed = cancelOwed_;
  }
  if (cancelOwed) {
    avoidance_.cancel();
    std::lock_guard lock(mutex_);
    cancelOwed_ = false;
  }
  std::optional<Task> active;
  {
    std::lock_guard lock(mutex_);
    const std::optional<TaskId> before = state_.queue.active() ? std::optional(state_.queue.active()->id) : std::nullopt;
    if (const Task* task = state_.queue.startNext()) {
      active = *task;
      if (before != task->id) {
        std::cerr << "high-level planning: task " << task->id << " (" << toString(task->kind) << ") active" << std::endl;
        checkpoint();
      }
    }
  }
  if (!active) return stopStrayDrive();
  strayChecked_ = true;
  if (active->kind == TaskKind::GoTo) runGoTo(*active);
  if (active->kind == TaskKind::Explore) runExplore(*active);
}

std::string HighLevelPlanningService::blockActiveTask() {
  std::lock_guard lock(mutex_);
  const Task* active = state_.queue.active();
  if (!active) return "the task loop's step (no task active)";
  const Task task = *active;
  finish(task, TaskState::Blocked, "its step failed " + std::to_string(InputFollower::kAttemptsPerRecord) +
                                       " times in a row (the module's log says why)");
  cancelOwed_ = true;
  return "task " + std::to_string(task.id);
}

// Once after a start with no task active: a drive of an ended task the module may have left
// running when it was killed is stopped.
void HighLevelPlanningService::stopStrayDrive() {
  if (strayChecked_) return;
  const DriveProgress drive = avoidance_.driveStatus();
  strayChecked_ = true;
  if (!drive.active()) return;
  std::lock_guard lock(mutex_);
  for (const Task& task : state_.queue.tasks())
    if (task.drive == drive.request) cancelOwed_ = true;
}

void HighLevelPlanningService::runGoTo(const Task& task) {
  const std::string what = "driving to " + describeGoal(task.goal);
  if (task.drive == 0) return applyDrive(task, startDrive(task, task.goal, what), what);
  // After a restart the drive is asked for again with its request ID: the CollisionAvoidance
  // module answers the drive it runs (or ran last) for it, or starts it anew.
  const DriveProgress drive =
      confirmedDrive_ == task.drive ? avoidance_.driveStatus() : avoidance_.driveTo(task.goal, task.drive);
  confirmedDrive_ = task.drive;
  applyDrive(task, drive, what);
}

DriveProgress HighLevelPlanningService::startDrive(const Task& task, const PlanGoal& goal, const std::string& what) {
  const std::uint64_t request = driveIds_();
  {
    std::lock_guard lock(mutex_);
    if (!stillActive(task)) return {};
    state_.queue.setProgress(request, state_.queue.active()->drives + 1, 0.0, what);
    checkpoint();
  }
  health_.add("drives");
  const DriveProgress drive = avoidance_.driveTo(goal, request);
  confirmedDrive_ = request;
  return drive;
}

void HighLevelPlanningService::applyDrive(const Task& task, const DriveProgress& drive, const std::string& what) {
  std::lock_guard lock(mutex_);
  if (!stillActive(task)) return;
  const Task& now = *state_.queue.active();
  if (drive.request != now.drive) {
    if (drive.request == 0) return;  // the task ended meanwhile
    finish(now, TaskState::Blocked,
           "the CollisionAvoidance module took another drive (request " + std::to_string(drive.request) + ")");
    return;
  }
  switch (drive.phase) {
    case DrivePhase::Reached: return finish(now, TaskState::Reached, {});
    case DrivePhase::Failed: return finish(now, TaskState::Blocked, drive.reason);
    case DrivePhase::Idle: return finish(now, TaskState::Blocked, "the drive was cancelled at the CollisionAvoidance module");
    default: state_.queue.setProgress(now.drive, now.drives, drive.distanceLeftM, what + ": " + toString(drive.phase));
  }
}

void HighLevelPlanningService::runExplore(const Task& task) {
  if (explorerTask_ != task.id) {
    explorer_.emplace(makeExplorationStrategy(options_.strategy, config_.exploration), config_.exploration);
    explorerTask_ = task.id;
    explorerDrive_ = 0;
  }
  DriveOutcome outcome = DriveOutcome::None;
  DriveProgress drive;
  if (explorerDrive_ != 0 && explorerDrive_ == task.drive) {
    drive = avoidance_.driveStatus();
    outcome = drive.request == explorerDrive_ ? outcomeOf(drive) : DriveOutcome::Failed;
  }
  try {
    if (cache_.refresh()) planner_.setMap(cache_.map());
  } catch (const Error& e) {
    health_.setError("kernel", e.what());
    return;
  }
  if (cache_.empty()) return progress(task, "exploring: waiting for the kernel's first region");
  const std::optional<Pose2D> robot = robotPose();
  if (!robot) return progress(task, "exploring: waiting for the robot's pose (" + options_.poseSource + ")");
  const Pose2D start = *robot;
  const PathLength pathLength = plannerPathLength(planner_, start);
  const ExplorationInput input{planner_.map(), start, summary_.current};
  const ExplorerStep next = explorer_->update(input, outcome, now(), pathLength);
  switch (next.action) {
    case ExplorerStep::Action::DriveTo: {
      const std::string what = "exploring: " + next.goal.reason;
      const DriveProgress started = startDrive(task, PlanGoal::at(next.goal.point), what);
      explorerDrive_ = started.request;
      return;
    }
    case ExplorerStep::Action::Done: {
      if (outcome == DriveOutcome::Driving) avoidance_.cancel();
      std::lock_guard lock(mutex_);
      if (stillActive(task)) finish(*state_.queue.active(), TaskState::Done, {});
      return;
    }
    case ExplorerStep::Action::Keep:
      return progress(task, "exploring: " + next.goal.reason + (drive.request ? ": " + toString(drive.phase) : ""),
                      drive.distanceLeftM);
  }
}

void HighLevelPlanningService::progress(const Task& task, const std::string& text, double distanceLeftM) {
  std::lock_guard lock(mutex_);
  if (!stillActive(task)) return;
  const Task& now = *state_.queue.active();
  state_.queue.setProgress(now.drive, now.drives, distanceLeftM, text);
}

void HighLevelPlanningService::finish(const Task& task, TaskState outcome, const std::string& reason) {
  state_.queue.finish(outcome, reason);
  health_.add(toString(outcome));
  std::cerr << "high-level planning: task " << task.id << " " << toString(outcome)
            << (reason.empty() ? "" : ": " + reason) << std::endl;
  checkpoint();
}

bool HighLevelPlanningService::stillActive(const Task& task) const {
  const Task* active = state_.queue.active();
  return active && active->id == task.id;
}

}  // namespace rgnav
