// The input-following thread of a module (see InputFollower.h).
#include "servers/common/InputFollower.h"

#include "core/common/Errors.h"

namespace rgnav {

InputFollower::InputFollower(ModuleHealth& health, std::string source, std::function<bool()> step,
                             std::chrono::milliseconds idle)
    : health_(health), source_(std::move(source)), step_(std::move(step)), idle_(idle) {}

InputFollower::~InputFollower() { stop(); }

void InputFollower::start() {
  thread_ = std::thread([this] { run(); });
}

void InputFollower::stop() {
  stopping_ = true;
  if (thread_.joinable()) thread_.join();
}

void InputFollower::run() {
  while (!stopping_) {
    try {
      if (!step_()) std::this_thread::sleep_for(idle_);
      health_.clearError(source_);
    } catch (const Error& e) {
      health_.setError(source_, e.what());
      std::this_thread::sleep_for(idle_ * 10);
    }
  }
}

}  // namespace rgnav
