// InputFollower: the thread with which a module follows its input modules by ID. It calls `step`
// until stopped, sleeps `idle` after a step that found nothing new, and records a typed error
// (an input module away or restarting) as the health error of `source`, retrying after ten idle
// periods; the next good step clears it.
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
  // `step` returns false when there was nothing new.
  InputFollower(ModuleHealth& health, std::string source, std::function<bool()> step,
                std::chrono::milliseconds idle = std::chrono::milliseconds(10));
  ~InputFollower();
  InputFollower(const InputFollower&) = delete;
  InputFollower& operator=(const InputFollower&) = delete;

  void start();
  // Waits for the step under way to end; no step starts after.
  void stop();
  bool stopping() const { return stopping_; }

 private:
  void run();

  ModuleHealth& health_;
  std::string source_;
  std::function<bool()> step_;
  std::chrono::milliseconds idle_;
  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

}  // namespace rgnav
