// The Collision Avoidance module's follower, drives and checkpoint (see AvoidanceService.h).
#include "servers/collisionavoidance/AvoidanceService.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <thread>

#include "core/common/AtomicFile.h"
#include "core/nav/grid/PlanningErrors.h"

namespace rgnav {
namespace {

constexpr std::uint32_t kScanBatch = 50;
constexpr double kStandingSpeed = 0.02;    // m/s: the robot stands
constexpr double kDoorNearM = 1.5;         // blocked this near a gateway crossing of the plan: that door
// A drive to a goal found blocked this often in a row, each time within kStuckM of where it was
// blocked before, fails: the new plans from there lead nowhere (a goal too close to furniture the
// map does not hold, say), and the caller may choose another goal instead of waiting for ever.
constexpr std::uint32_t kMaxBlocksInPlace = 5;
constexpr double kStuckM = 0.5;
// The targets follow the odometry's drift against the map frame (new targets make the core plan
// anew), checked this often, once the drift exceeds these, and only while the goal is farther
// than kFrameSettledM along the targets: near the goal a changed goal would come too late to
// brake for it.
constexpr double kFrameCheckS = 2.0;
constexpr double kFrameDriftM = 0.1;
constexpr double kFrameDriftRad = 0.03;
constexpr double kFrameSettledM = 3.0;

DriveRecord loadCheckpoint(const std::string& file) {
  const std::optional<std::string> saved = file.empty() ? std::nullopt : readCheckpoint(file);
  if (!saved) return {};
  DriveRecord drive = deserializeDrive(*saved, file);
  // An active drive resumes from where the robot stands: planned again toward its goal, or on
  // along its given targets.
  if (drive.progress.active()) drive.progress.phase = drive.progress.hasGoal ? DrivePhase::Planning : DrivePhase::Driving;
  return drive;
}

bool finite(const Pose2D& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.theta); }

double distance(const Pose2D& a, const Pose2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

}  // namespace

AvoidanceService::AvoidanceService(const CollisionAvoidanceConfig& config, const ClientSettings& settings,
                                   AvoidanceServiceOptions options, ModuleHealth& health)
    : config_(config),
      options_(std::move(options)),
      health_(health),
      laser_(settings, options_.laserObject),
      base_(settings, options_.baseObject),
      lld_(settings, options_.driveObject),
      planner_(settings, options_.plannerObject),
      obstacles_(config.obstacleMap),
      frameSource_(options_.poseSource, settings,
             {options_.truthObject, options_.scanMapperObject, options_.localizationObject, options_.laserObject},
             health),
      drive_(loadCheckpoint(options_.checkpointFile)),
      retry_(health),
      follower_(health, "laser", [this] { return step(); }, [this] { return skipScan(); }) {
  validate(config_);
  validate(options_.footprint);
  health_.set("resumed_drive", drive_.progress.active() ? 1 : 0);
}

DriveProgress AvoidanceService::driveTo(std::uint64_t request, const PlanGoal& goal) {
  if (request == 0) throw InvalidArgumentError("request ID 0");
  if (!std::isfinite(goal.point.x()) || !std::isfinite(goal.point.y())) throw InvalidArgumentError("goal not finite");
  std::lock_guard lock(mutex_);
  if (drive_.progress.request == request) return drive_.progress;
  drive_ = {};
  drive_.progress.request = request;
  drive_.progress.phase = DrivePhase::Planning;
  drive_.progress.hasGoal = true;
  drive_.progress.goal = goal;
  ++generation_;
  health_.add("drives");
  checkpoint();
  return drive_.progress;
}

DriveProgress AvoidanceService::followTargets(std::uint64_t request, std::vector<TargetPose> targets) {
  if (request == 0) throw InvalidArgumentError("request ID 0");
  if (targets.empty()) throw InvalidArgumentError("no targets");
  for (const TargetPose& t : targets)
    if (!finite(t.pose)) throw InvalidArgumentError("a target is not finite");
  std::lock_guard lock(mutex_);
  if (drive_.progress.request == request) return drive_.progress;
  drive_ = {};
  drive_.progress.request = request;
  drive_.progress.phase = DrivePhase::Driving;
  drive_.progress.targetCount = static_cast<std::uint32_t>(targets.size());
  drive_.targets = std::move(targets);
  ++generation_;
  health_.add("drives");
  checkpoint();
  return drive_.progress;
}

void AvoidanceService::cancel() {
  std::lock_guard lock(mutex_);
  drive_.progress.phase = DrivePhase::Idle;
  drive_.progress.reason.clear();
  stopOwed_ = true;
  ++generation_;
  checkpoint();
}

DriveProgress AvoidanceService::status() {
  std::lock_guard lock(mutex_);
  return drive_.progress;
}

void AvoidanceService::checkpoint() {
  if (options_.checkpointFile.empty() || !retry_.due()) return;
  try {
    writeFileAtomically(options_.checkpointFile, serializeDrive(drive_));
    retry_.succeeded();
  } catch (const FileError& e) {
    retry_.failed(e.what());
  }
}

bool AvoidanceService::current(std::uint64_t generation) { return generation == generation_; }

void AvoidanceService::record(std::uint64_t generation, DrivePhase phase, const std::string& reason) {
  std::lock_guard lock(mutex_);
  if (!current(generation)) return;
  const bool ends = phase == DrivePhase::Reached || phase == DrivePhase::Failed;
  drive_.progress.phase = phase;
  drive_.progress.reason = reason;
  if (phase == DrivePhase::Reached) {
    drive_.progress.targetIndex = drive_.progress.targetCount;
    drive_.progress.distanceLeftM = 0.0;
  }
  if (ends) checkpoint();
}

void AvoidanceService::prepare() {
  if (core_) return;
  const MotionLimits limits = lld_.limits();
  chainBase_ = lld_.driveStatus().drive.chainId;
  core_.emplace(config_, options_.footprint, limits);
  std::cerr << "collision avoidance: chains continue above " << chainBase_ << std::endl;
}

RobotState AvoidanceService::robotState() {
  const DataId latest = base_.latestOdometryId();
  if (latest == 0) throw NotAvailableError("the Base has no odometry yet");
  const auto batch = base_.odometrySince(latest - 1, 1);
  if (batch.records.empty()) throw NotAvailableError("the Base's newest odometry reading is gone");
  const OdometryReading& r = batch.records.back();
  stateWall_ = std::chrono::steady_clock::now();
  stateStamp_ = r.stamp;
  return {r.stamp, r.pose, r.translationalVelocity, r.rotationalVelocity};
}

DriveRecord AvoidanceService::takeDrive(std::uint64_t& generation) {
  std::lock_guard lock(mutex_);
  generation = generation_;
  return drive_;
}

bool AvoidanceService::step() {
  prepare();
  std::uint64_t generation = 0;
  const DriveRecord drive = takeDrive(generation);
  bool stopNow = false;
  {
    std::lock_guard lock(mutex_);
    std::swap(stopNow, stopOwed_);
  }
  if (stopNow) lld_.stop();
  if (!drive.progress.active() && generation == appliedGeneration_) {
    // Idle: no scans are read, so a lock-step simulator (the demo's tour) is not paced by a module
    // that does not drive; the next drive starts from the newest scan.
    following_ = false;
    return stopNow;
  }
  if (!following_) {
    const DataId latest = laser_.latestId();
    if (latest > lastScan_ + 1) lastScan_ = latest - 1;
    following_ = true;
  }
  const auto batch = laser_.scansSince(lastScan_, kScanBatch);
  if (batch.records.empty()) return false;
  for (const LaserScan& scan : batch.records) obstacles_.add(scan);
  const LaserScan& scan = batch.records.back();
  lastScan_ = scan.id;
  health_.add("scans", batch.records.size());
  frameSource_.refresh(batch.records);
  if (!frameSource_.frame()) return true;  // where the robot stands in the map is not known yet
  mapFromOdometry_ = *frameSource_.frame();
  const RobotState state = robotState();

  if (generation != appliedGeneration_) {  // a new drive (or a cancel): the core starts afresh
    appliedGeneration_ = generation;
    lastPlan_.reset();
    blockedAt_.reset();
    lastBlock_.reset();
    blocksInPlace_ = 0;
    std::vector<TargetPose> rest;
    if (drive.progress.phase == DrivePhase::Driving)
      rest.assign(drive.targets.begin() + drive.progress.targetIndex, drive.targets.end());
    setCoreTargets(rest);
  }
  if (!drive.progress.active()) return true;
  if (!settled_) {  // after a start: stand before the first chain of this module
    if (std::abs(state.velocity) > kStandingSpeed) {
      lld_.stop();
      return true;
    }
    settled_ = true;
  }
  const Pose2D here = toMap(mapFromOdometry_, state.pose);
  switch (drive.progress.phase) {
    case DrivePhase::Planning:
    case DrivePhase::Replanning: plan(drive, generation, here); break;
    default: decide(drive, generation, state); break;
  }
  return true;
}

std::string AvoidanceService::skipScan() { return "scan " + std::to_string(++lastScan_); }

void AvoidanceService::plan(const DriveRecord& drive, std::uint64_t generation, const Pose2D& here) {
  if (blockedAt_ && lastPlan_) {
    for (const GraphNodeView& node : lastPlan_->plan.route) {
      if (std::hypot(node.position.x() - blockedAt_->x, node.position.y() - blockedAt_->y) > kDoorNearM) continue;
      try {
        planner_.replanDoorBlocked(node.gateway);
        health_.add("doors_reported");
      } catch (const BadArgumentError&) {
        // not a door: planned around below
      } catch (const NoPathError&) {
        // the plan from the old start has no way: the plan from here below decides
      }
      break;
    }
  }
  PlanRecord made;
  try {
    made = planner_.plan(here, drive.progress.goal);
  } catch (const NoPathError& e) {
    record(generation, DrivePhase::Failed, e.what());
    return;
  } catch (const InvalidArgumentError& e) {  // a goal the planner refuses (an unknown region, say)
    record(generation, DrivePhase::Failed, e.what());
    return;
  } catch (const NotAvailableError& e) {
    health_.setError("planner", e.what());
    return;
  }
  health_.clearError("planner");
  health_.add("plans");
  std::lock_guard lock(mutex_);
  if (!current(generation)) return;
  lastPlan_ = made;
  blockedAt_.reset();
  drive_.targets = made.plan.targets;
  drive_.progress.plan = made.id;
  drive_.progress.targetIndex = 0;
  drive_.progress.targetCount = static_cast<std::uint32_t>(made.plan.targets.size());
  drive_.progress.phase = DrivePhase::Driving;
  checkpoint();
  setCoreTargets(drive_.targets);
}

void AvoidanceService::setCoreTargets(const std::vector<TargetPose>& targets) {
  std::vector<Pose2D> odometry;
  for (const TargetPose& t : targets) odometry.push_back(toOdometry(mapFromOdometry_, t.pose));
  core_->setTargets(std::move(odometry));
  targetsFrame_ = mapFromOdometry_;
}

void AvoidanceService::followFrameDrift(const Pose2D& robot) {
  double left = 0.0;
  Pose2D from = robot;
  for (const Pose2D& t : core_->targets()) {
    left += distance(from, t);
    from = t;
  }
  if (left < kFrameSettledM) return;
  const Pose2D drift = between(targetsFrame_, mapFromOdometry_);
  if (std::hypot(drift.x, drift.y) < kFrameDriftM && std::abs(drift.theta) < kFrameDriftRad) return;
  std::vector<Pose2D> moved;
  for (const Pose2D& t : core_->targets()) moved.push_back(toOdometry(mapFromOdometry_, toMap(targetsFrame_, t)));
  core_->setTargets(std::move(moved));
  targetsFrame_ = mapFromOdometry_;
}

void AvoidanceService::decide(const DriveRecord& drive, std::uint64_t generation, const RobotState& state) {
  if (state.stamp - targetsFrameStamp_ >= kFrameCheckS) {
    followFrameDrift(state.pose);
    targetsFrameStamp_ = state.stamp;
  }
  const ObstacleGrid grid = obstacles_.grid();
  const AvoidanceDecision decision = core_->update(state, std::span<const ObstacleGrid>(&grid, 1));
  if (options_.trace && decision.action != AvoidanceAction::Keep) traceDecision(state, decision);
  if (decision.chain) send(*decision.chain);
  if (decision.stopNow) lld_.stop();
  switch (decision.action) {
    case AvoidanceAction::Drive: record(generation, DrivePhase::Driving); break;
    case AvoidanceAction::Wait: record(generation, DrivePhase::Waiting, decision.reason); break;
    case AvoidanceAction::GoalReached: record(generation, DrivePhase::Reached); break;
    case AvoidanceAction::Blocked:
      if (!drive.progress.hasGoal) {
        record(generation, DrivePhase::Failed, "blocked: " + decision.reason);
        break;
      }
      blockedAt_ = toMap(mapFromOdometry_, state.pose);
      blocksInPlace_ = lastBlock_ && distance(*lastBlock_, *blockedAt_) < kStuckM ? blocksInPlace_ + 1 : 1;
      lastBlock_ = blockedAt_;
      if (blocksInPlace_ >= kMaxBlocksInPlace) {
        record(generation, DrivePhase::Failed,
               "blocked: " + std::to_string(blocksInPlace_) + " plans in a row found no way on from here (" +
                   decision.reason + ")");
        break;
      }
      {
        std::lock_guard lock(mutex_);
        if (current(generation)) ++drive_.progress.replans;
      }
      health_.add("replans");
      record(generation, DrivePhase::Replanning, decision.reason);
      break;
    case AvoidanceAction::Keep: break;
  }
  const std::vector<Pose2D>& left = core_->targets();
  double remaining = 0.0;
  Pose2D from = state.pose;
  for (const Pose2D& t : left) {
    remaining += distance(from, t);
    from = t;
  }
  std::lock_guard lock(mutex_);
  if (!current(generation) || drive_.progress.phase == DrivePhase::Reached) return;
  const auto index = static_cast<std::uint32_t>(
      drive_.progress.targetCount - std::min<std::size_t>(left.size(), drive_.progress.targetCount));
  drive_.progress.distanceLeftM = remaining;
  if (index == drive_.progress.targetIndex) return;
  drive_.progress.targetIndex = index;
  checkpoint();  // a restart drives on from here
}

void AvoidanceService::traceDecision(const RobotState& state, const AvoidanceDecision& decision) const {
  char line[256];
  const Pose2D goal = core_->targets().empty() ? Pose2D{} : core_->targets().back();
  std::snprintf(line, sizeof line, "t=%.2f odometry=(%.2f %.2f %.2f) v=%.2f targets=%zu goal=(%.2f %.2f) %s: %s",
                state.stamp, state.pose.x, state.pose.y, state.pose.theta, state.velocity, core_->targets().size(),
                goal.x, goal.y, toString(decision.action).c_str(), decision.reason.c_str());
  std::cerr << line;
  if (decision.chain)
    std::cerr << " chain " << decision.chain->chain.length() << " m to (" << decision.chain->chain.end().x << " "
              << decision.chain->chain.end().y << ") from " << decision.chain->startSpeed << " m/s";
  std::cerr << std::endl;
}

void AvoidanceService::send(DriveChain chain) {
  chain.id += chainBase_;
  // The drive replaces its chain at once, so the chain goes out when the odometry clock reaches
  // its start (one planning latency after the reading it was planned from), not before.
  std::this_thread::sleep_until(stateWall_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                 std::chrono::duration<double>(chain.startTime - stateStamp_)));
  try {
    lld_.setChain(chain);
  } catch (const BadArgumentError& e) {
    // Another sender or a drive that kept a higher ID: continue above what it accepted.
    health_.add("chains_refused");
    chainBase_ = lld_.driveStatus().drive.chainId;
    std::cerr << "collision avoidance: chain " << chain.id << " refused (" << e.what() << "), continuing above "
              << chainBase_ << std::endl;
    return;
  }
  health_.add("chains_sent");
  std::lock_guard lock(mutex_);
  ++drive_.progress.chainsSent;
}

}  // namespace rgnav
