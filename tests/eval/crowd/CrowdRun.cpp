// Driving and judging the crowd evaluation's goals (see CrowdRun.h).
#include "tests/eval/crowd/CrowdRun.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "clientlibs/collisionavoidance/CollisionAvoidanceClient.h"
#include "tests/eval/crowd/TruePoseProbe.h"
#include "tests/support/cluster/Interruption.h"

namespace rgnav {

using Clock = std::chrono::steady_clock;

namespace {

constexpr auto kPollPeriod = std::chrono::milliseconds(100);
constexpr auto kReportPeriod = std::chrono::seconds(10);  // verbose: a progress line this often
constexpr double kPathStepM = 0.05;  // a path point whenever the robot moved this far

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// The CAM's status, or nothing while it does not answer (killed, restarting).
std::optional<DriveProgress> statusOf(CollisionAvoidanceClient& cam) {
  try {
    return cam.driveStatus();
  } catch (const ModuleUnavailableError&) {
    return std::nullopt;
  } catch (const ModuleFailedError&) {
    return std::nullopt;
  }
}

GoalOutcome driveOne(CollisionAvoidanceClient& cam, TruePoseProbe& probe, const Eigen::Vector2d& goal,
                     const CrowdRunOptions& options) {
  GoalOutcome outcome;
  outcome.goal = goal;
  const PlanGoal planGoal = PlanGoal::at(goal);
  std::uint64_t request = 0;
  const auto begin = Clock::now();
  std::optional<Pose2D> previous;
  auto nextReport = begin + kReportPeriod;
  for (auto next = begin;; next += kPollPeriod) {
    testing::sleepUntilOrInterrupted(next);
    if (seconds(Clock::now() - begin) > options.goalTimeoutS) {
      outcome.finalState = "timeout";
      try {
        cam.cancel();
      } catch (const Error&) {
      }
      break;
    }
    const TrueSample here = probe.latest();
    if (previous) outcome.distanceM += std::hypot(here.pose.x - previous->x, here.pose.y - previous->y);
    previous = here.pose;
    const Eigen::Vector2d position(here.pose.x, here.pose.y);
    if (outcome.path.empty() || (position - outcome.path.back()).norm() > kPathStepM) outcome.path.push_back(position);
    outcome.finalErrorM = std::hypot(here.pose.x - goal.x(), here.pose.y - goal.y());
    std::optional<DriveProgress> status = request == 0 ? std::nullopt : statusOf(cam);
    if (request == 0 || (status && status->request != request)) {
      try {
        status = cam.driveTo(planGoal, request);  // the same request again if the CAM lost it
        request = status->request;
      } catch (const ModuleUnavailableError&) {
        continue;
      }
    }
    if (!status) continue;
    if (options.verbose && (toString(status->phase) != outcome.finalState || next >= nextReport)) {
      std::fprintf(stderr, "  %6.1f s: %-10s at (%.2f, %.2f) target %u/%u, %.1f m left, %llu chains %s\n",
                   seconds(Clock::now() - begin), toString(status->phase).c_str(), here.pose.x, here.pose.y,
                   status->targetIndex, status->targetCount, status->distanceLeftM,
                   static_cast<unsigned long long>(status->chainsSent), status->reason.c_str());
      nextReport = next + kReportPeriod;
    }
    outcome.finalState = toString(status->phase);
    outcome.replans = status->replans;
    outcome.reason = status->reason;
    if (status->phase == DrivePhase::Failed) break;
    if (status->phase == DrivePhase::Reached && outcome.finalErrorM <= options.toleranceM) {
      outcome.reached = true;
      break;
    }
  }
  if (previous) {
    const Eigen::Vector2d end(previous->x, previous->y);
    if (outcome.path.back() != end) outcome.path.push_back(end);
  }
  outcome.seconds = seconds(Clock::now() - begin);
  return outcome;
}

}  // namespace

std::size_t CrowdOutcome::reached() const {
  std::size_t n = 0;
  for (const GoalOutcome& g : goals) n += g.reached;
  return n;
}

double CrowdOutcome::meanSpeedMps() const {
  double distance = 0.0, time = 0.0;
  for (const GoalOutcome& g : goals)
    if (g.reached) {
      distance += g.distanceM;
      time += g.seconds;
    }
  return time > 0.0 ? distance / time : 0.0;
}

CrowdOutcome driveGoals(const ClientSettings& settings, const std::vector<Eigen::Vector2d>& goals,
                        const CrowdRunOptions& options) {
  CollisionAvoidanceClient cam(settings);
  TruePoseProbe probe(settings);
  CrowdOutcome outcome;
  for (std::size_t i = 0; i < goals.size(); ++i) {
    if (options.verbose) std::fprintf(stderr, "goal %zu: to (%.2f, %.2f)\n", i + 1, goals[i].x(), goals[i].y());
    outcome.goals.push_back(driveOne(cam, probe, goals[i], options));
    const GoalOutcome& g = outcome.goals.back();
    if (options.verbose)
      std::printf("goal %2zu (%6.2f, %5.2f): %-9s %6.1f s %6.1f m error %.2f m replans %u %s\n", i + 1, g.goal.x(),
                  g.goal.y(), g.reached ? "reached" : g.finalState.c_str(), g.seconds, g.distanceM, g.finalErrorM,
                  g.replans, g.reason.c_str());
    std::fflush(stdout);
  }
  return outcome;
}

}  // namespace rgnav
