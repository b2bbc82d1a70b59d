// The input-following thread of a module (see InputFollower.h).
#include "servers/common/InputFollower.h"

#include <iostream>

#include "clientlibs/common/ClientConnection.h"
#include "core/common/Errors.h"

namespace rgnav {

InputFollower::InputFollower(ModuleHealth& health, std::string source, std::function<bool()> step,
                             std::function<std::string()> skip, std::chrono::milliseconds idle)
    : health_(health), source_(std::move(source)), step_(std::move(step)), skip_(std::move(skip)), idle_(idle) {}

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
      failures_ = 0;
      health_.clearError(source_);
    } catch (const ModuleUnavailableError& e) {
      health_.setError(source_, e.what());
      std::this_thread::sleep_for(idle_ * 10);
    } catch (const ModuleFailedError& e) {
      health_.setError(source_, e.what());
      std::this_thread::sleep_for(idle_ * 10);
    } catch (const std::exception& e) {
      stepFailed(e.what());
    } catch (...) {
      stepFailed("an exception of unknown type");
    }
  }
}

void InputFollower::stepFailed(const std::string& what) {
  health_.add("input_failures");
  health_.setError(source_, what);
  std::cerr << source_ << ": an input record failed: " << what << std::endl;
  if (++failures_ < kAttemptsPerRecord) {
    std::this_thread::sleep_for(idle_);
    return;
  }
  failures_ = 0;
  try {
    const std::string skipped = skip_();
    health_.add("input_records_skipped");
    std::cerr << source_ << ": skipped " << skipped << " after " << kAttemptsPerRecord << " failed attempts"
              << std::endl;
  } catch (const std::exception& e) {
    health_.setError(source_, std::string("cannot skip the failing record: ") + e.what());
  }
}

}  // namespace rgnav
