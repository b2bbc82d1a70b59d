// InputFollower: the thread with which a module follows its input modules by ID. It calls `step`
// until stopped and sleeps `idle` after a step that found nothing new. No error ends the thread
// (or the process):
//  - an input module away, restarting or failing (ModuleUnavailableError, ModuleFailedError) is
//    the health error of `source`, retried after ten idle periods without limit;
//  - any other error is taken to come from the input record the step was working on: it is
//    logged, counted (health "input_failures") and retried; once the same record failed
//    kAttemptsPerRecord times in a row, `skip` drops it (health "input_records_skipped") and
//    the module goes on with the next one.
// The next good step clears the health error.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <string>
#include <thread>

#include "servers/common/ModuleHealth.h"

namespace rgnav {

class InputFollower {
 public:
  // Attempts a bad input record gets before it is skipped.
  static constexpr int kAttemptsPerRecord = 3;

  // `step` returns false when there was nothing new. `skip` drops the record the failing step
  // was working on and says which record it was.
  InputFollower(ModuleHealth& health, std::string source, std::function<bool()> step,
                std::function<std::string()> skip, std::chrono::milliseconds idle = std::chrono::milliseconds(10));
  ~InputFollower();
  InputFollower(const InputFollower&) = delete;
  InputFollower& operator=(const InputFollower&) = delete;

  void start();
  // Waits for the step under way to end; no step starts after.
  void stop();
  bool stopping() const { return stopping_; }

 private:
  void run();
  void stepFailed(const std::string& what);

  ModuleHealth& health_;
  std::string source_;
  std::function<bool()> step_;
  std::function<std::string()> skip_;
  std::chrono::milliseconds idle_;
  int failures_ = 0;  // of the current record, in a row
  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

}  // namespace rgnav
