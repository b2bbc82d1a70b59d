// HighLevelPlanningService: the High-Level Planning module's work behind its servant (thesis
// chapter 1's tasks, figure 5.1, 6.1.3's naming by the user, chapter 7's exploration). The servant
// queues tasks (TaskQueue.h) and answers naming questions (NamingDialog.h); one thread (the task
// loop, every pollPeriodS) carries out the active task and keeps the dialog:
//   - goTo: a drive of the CollisionAvoidance module to the task's goal (driveTo; the module plans
//     it with the PathPlanning module and drives the Low-Level Drive); its driveStatus is polled
//     until the drive is reached (task Reached) or failed (task Blocked with the module's reason).
//   - explore: an Explorer (core/nav/exploration/Explorer.h, strategy --strategy) on the RG
//     Mapping Kernel's map (KernelMapCache.h, as the PathPlanning module takes it) and the robot's
//     pose (RobotPose.h); its goals become driveTo drives to their points; driving distances for
//     the strategy come from a route planner of the module's own on the same map. Done when the
//     explorer is.
//   - a task whose step keeps failing (an error that is not a module away, InputFollower.h) ends
//     Blocked with that said, so one bad task does not hold up the queue.
//   - cancel and stop: the task ends Cancelled; if it was active (stop: always) the
//     CollisionAvoidance module is told to cancel, which brakes the robot.
//   - naming: the kernel's summary names the region the robot is in; an unnamed one gets a
//     question; an answer names the region in the kernel (nameRegion) and ends the question.
//     Nothing waits for an answer.
// Request IDs: each drive gets a new random request ID, written to the checkpoint before the drive
// is asked for, so that a restarted module asks the CollisionAvoidance module again with the same
// ID and gets the drive it started (or its outcome) instead of a second one.
// State survives (TaskCheckpoint.h): the queue, the dialog and the latest answered requests are
// checkpointed whenever they change; a restarted module starts its active task again - a goTo with
// its drive's request ID, an exploration with a new explorer on the kernel's map - and a restarted
// module with no task active stops a drive of an ended task that is still running.
// No module of the robot reads the simulator's ground truth; neither does this one.
// Health: tasks, drives, reached, blocked, cancelled, questions, answers; errors "kernel", "pose",
// "avoidance".
#pragma once

#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "clientlibs/collisionavoidance/CollisionAvoidanceClient.h"
#include "clientlibs/common/RequestIds.h"
#include "clientlibs/pathplanning/KernelMapCache.h"
#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "core/nav/exploration/Explorer.h"
#include "core/nav/tasks/HighLevelPlanningConfig.h"
#include "servers/common/CheckpointRetry.h"
#include "servers/common/InputFollower.h"
#include "servers/common/ModuleHealth.h"
#include "servers/highlevelplanning/RobotPose.h"
#include "servers/highlevelplanning/TaskCheckpoint.h"

namespace rgnav {

struct HighLevelPlanningServiceOptions {
  std::string kernelObject = "RGMappingKernel";
  std::string avoidanceObject = "CollisionAvoidance";
  std::string poseSource = "scanmapper";  // RobotPose.h
  std::string poseObject;                 // empty: the pose source's usual object name
  std::string strategy = "rg";            // ExplorationStrategy.h
  std::string checkpointFile;             // empty: no checkpoints
};

class HighLevelPlanningService {
 public:
  // Loads the checkpoint if there is one (FormatError if it is damaged). Contacts no module yet.
  // ConfigError for a bad configuration, pose source or strategy.
  HighLevelPlanningService(const HighLevelPlanningConfig& config, const ClientSettings& settings,
                           HighLevelPlanningServiceOptions options, ModuleHealth& health);

  void start() { follower_.start(); }
  void stop() { follower_.stop(); }

  // InvalidArgumentError for a request ID 0 (and what TaskQueue refuses).
  Task goTo(std::uint64_t request, const PlanGoal& goal);
  Task explore(std::uint64_t request);
  Task stopAll(std::uint64_t request);
  // `id` 0: the active task. NotAvailableError for no such task.
  Task cancel(std::uint64_t request, TaskId id);
  Task task(TaskId id);  // NotAvailableError for a task not kept
  std::vector<Task> tasks();
  std::vector<NamingQuestion> questions();
  // NotAvailableError: no such question waits; what the kernel's nameRegion throws.
  void answer(std::uint64_t request, QuestionId question, const std::string& name);
  TaskId nextTaskId();

 private:
  // A task added by `add` (under lock) for `request`; counted and checkpointed if new.
  template <class Add>
  Task queue(std::uint64_t request, Add&& add);
  bool step();
  void pollKernel();
  std::optional<Pose2D> robotPose();  // fetched only where needed: the source may be away
  void runTask();
  void stopStrayDrive();
  // A task whose step failed kAttemptsPerRecord times in a row with an error that is not a module
  // away (InputFollower.h) ends blocked, and the robot is stopped; says which task it was.
  std::string blockActiveTask();
  void runGoTo(const Task& task);
  void runExplore(const Task& task);
  // A new drive for the active task `task` to `goal`: its request ID checkpointed, then asked for.
  DriveProgress startDrive(const Task& task, const PlanGoal& goal, const std::string& progress);
  // The drive's state as the active task's outcome or progress (nothing if `task` is no longer
  // the active one).
  void applyDrive(const Task& task, const DriveProgress& drive, const std::string& what);
  void progress(const Task& task, const std::string& text, double distanceLeftM = 0.0);
  void finish(const Task& task, TaskState outcome, const std::string& reason);
  bool stillActive(const Task& task) const;  // under lock
  void checkpoint();                          // under lock
  double now() const;

  HighLevelPlanningConfig config_;
  HighLevelPlanningServiceOptions options_;
  ModuleHealth& health_;

  // The task loop's own.
  RgMappingKernelClient kernel_;
  CollisionAvoidanceClient avoidance_;
  std::unique_ptr<RobotPose> pose_;
  KernelMapCache cache_;
  RoutePlanner planner_;
  RequestIds driveIds_;
  std::optional<Explorer> explorer_;
  TaskId explorerTask_ = 0;
  std::uint64_t explorerDrive_ = 0;  // the drive the explorer's goal went to (0: none yet)
  std::uint64_t confirmedDrive_ = 0; // a goTo drive the CollisionAvoidance module has answered for
  bool strayChecked_ = false;
  MapSummaryView summary_;
  std::optional<RgMapEventId> regionsRevision_;
  RegionId regionsCurrent_;
  std::vector<RegionSummaryView> regions_;
  const std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();

  // answer's kernel calls (servant threads, one at a time).
  std::mutex namingMutex_;
  RgMappingKernelClient namer_;

  mutable std::mutex mutex_;  // guards what follows (servant threads and the task loop)
  HighLevelPlanningState state_;
  bool cancelOwed_ = false;   // the active task was cancelled: the CollisionAvoidance module is to stop
  CheckpointRetry retry_;
  InputFollower follower_;
};

}  // namespace rgnav
