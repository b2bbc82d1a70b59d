// Restart decisions for one supervised module: restart policy, bounded restart intensity
// (at most max_restarts in a sliding window, then FATAL) and exponential backoff for runs
// that fail before they ever answer a ping. Pure logic: the caller passes the time in.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <string>

#include "core/supervision/ExitStatus.h"
#include "core/supervision/ModulePolicy.h"
#include "core/supervision/SupervisionClock.h"

namespace rgnav {

struct ExitInfo {
  ExitStatus status;
  bool stoppedByOperator = false;  // a deliberate stop is never restarted
};

struct RestartDecision {
  enum class Action { Restart, StayDown, Fatal };
  Action action;
  std::chrono::nanoseconds delay{0};  // wait this long before restarting (Restart only)
  std::string reason;                 // names the module and why
};

class RestartTracker {
 public:
  RestartTracker(std::string module, ModulePolicy policy);

  // The current run ended; decides what happens next. Once FATAL, every answer is Fatal.
  RestartDecision onExit(const ExitInfo& exit, SupervisionClock::time_point now);
  // The current run answered its first ping: its exit will be restarted without delay.
  void onReady();
  // An operator restarts the module by hand: forget FATAL, the restart history and the backoff.
  void reset();

  bool fatal() const { return fatal_; }
  std::uint64_t restartsTotal() const { return restartsTotal_; }
  int restartsInWindow(SupervisionClock::time_point now) const;

 private:
  std::chrono::nanoseconds backoff(int failuresBeforeReady) const;
  RestartDecision stayDown(const std::string& why) const;

  std::string module_;
  ModulePolicy policy_;
  bool ready_ = false;
  bool fatal_ = false;
  std::string fatalReason_;
  int failuresBeforeReady_ = 0;
  std::deque<SupervisionClock::time_point> restarts_;  // times of restarts, oldest first
  std::uint64_t restartsTotal_ = 0;
};

}  // namespace rgnav
