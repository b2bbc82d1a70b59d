// Restart policy, restart intensity and backoff arithmetic for one module.
#include "core/supervision/RestartTracker.h"

#include <algorithm>
#include <sstream>

namespace rgnav {
namespace {

std::string seconds(std::chrono::nanoseconds d) {
  std::ostringstream s;
  s << std::chrono::duration<double>(d).count() << " s";
  return s.str();
}

}  // namespace

RestartTracker::RestartTracker(std::string module, ModulePolicy policy)
    : module_(std::move(module)), policy_(policy) {}

RestartDecision RestartTracker::stayDown(const std::string& why) const {
  return {RestartDecision::Action::StayDown, std::chrono::nanoseconds(0), module_ + ": " + why};
}

RestartDecision RestartTracker::onExit(const ExitInfo& exit, SupervisionClock::time_point now) {
  if (fatal_) return {RestartDecision::Action::Fatal, std::chrono::nanoseconds(0), fatalReason_};
  const bool wasReady = ready_;
  ready_ = false;
  const std::string what = exit.status.describe();
  if (exit.stoppedByOperator) return stayDown("stopped by operator, " + what);
  if (policy_.restart == RestartPolicy::Temporary) return stayDown("temporary module " + what);
  if (policy_.restart == RestartPolicy::Transient && !exit.status.abnormal()) {
    return stayDown("transient module " + what);
  }
  while (!restarts_.empty() && now - restarts_.front() >= policy_.restartWindow) restarts_.pop_front();
  if (static_cast<int>(restarts_.size()) >= policy_.maxRestarts) {
    fatal_ = true;
    fatalReason_ = module_ + ": FATAL, " + what + " after " + std::to_string(restarts_.size()) +
                   " restarts within " + seconds(policy_.restartWindow) + " (max_restarts " +
                   std::to_string(policy_.maxRestarts) + "); staying down";
    return {RestartDecision::Action::Fatal, std::chrono::nanoseconds(0), fatalReason_};
  }
  failuresBeforeReady_ = wasReady ? 0 : failuresBeforeReady_ + 1;
  const std::chrono::nanoseconds delay = backoff(failuresBeforeReady_);
  restarts_.push_back(now);
  ++restartsTotal_;
  return {RestartDecision::Action::Restart, delay,
          module_ + ": " + what + (wasReady ? "" : " before answering a ping") + ", restart " +
              std::to_string(restarts_.size()) + " of " + std::to_string(policy_.maxRestarts) + " within " +
              seconds(policy_.restartWindow) + " in " + seconds(delay)};
}

void RestartTracker::onReady() {
  ready_ = true;
  failuresBeforeReady_ = 0;
}

void RestartTracker::reset() {
  fatal_ = false;
  fatalReason_.clear();
  ready_ = false;
  failuresBeforeReady_ = 0;
  restarts_.clear();
}

int RestartTracker::restartsInWindow(SupervisionClock::time_point now) const {
  return static_cast<int>(std::count_if(restarts_.begin(), restarts_.end(), [&](SupervisionClock::time_point t) {
    return now - t < policy_.restartWindow;
  }));
}

// The n-th consecutive failure before ready waits backoff_initial * 2^(n-1), capped at backoff_max.
std::chrono::nanoseconds RestartTracker::backoff(int failuresBeforeReady) const {
  if (failuresBeforeReady == 0) return std::chrono::nanoseconds(0);
  std::chrono::nanoseconds delay = policy_.backoffInitial;
  for (int k = 1; k < failuresBeforeReady && delay.count() > 0 && delay < policy_.backoffMax; ++k) delay *= 2;
  return std::min(delay, policy_.backoffMax);
}

}  // namespace rgnav
