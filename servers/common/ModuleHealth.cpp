// ModuleHealth bookkeeping (see ModuleHealth.h).
#include "servers/common/ModuleHealth.h"

#include <unistd.h>

#include <algorithm>

namespace rgnav {

ModuleHealth::ModuleHealth() { status_.pid = static_cast<std::uint32_t>(::getpid()); }

void ModuleHealth::setName(const std::string& name) {
  std::lock_guard lock(mutex_);
  status_.name = name;
}

void ModuleHealth::setState(ModuleRunState state) {
  std::lock_guard lock(mutex_);
  status_.state = state;
}

void ModuleHealth::add(const std::string& counter, std::uint64_t amount) {
  std::lock_guard lock(mutex_);
  status_.counters[counter] += amount;
}

void ModuleHealth::set(const std::string& counter, std::uint64_t value) {
  std::lock_guard lock(mutex_);
  status_.counters[counter] = value;
}

void ModuleHealth::record(const std::string& source, const std::string& message, bool degrades) {
  Error& entry = errors_[source];
  if (entry.message != message || entry.degrades != degrades) entry = {++errorOrder_, message, degrades};
}

void ModuleHealth::setError(const std::string& source, const std::string& message) {
  std::lock_guard lock(mutex_);
  record(source, message, false);
}

void ModuleHealth::setDegraded(const std::string& source, const std::string& reason) {
  std::lock_guard lock(mutex_);
  record(source, reason, true);
}

void ModuleHealth::clearError(const std::string& source) {
  std::lock_guard lock(mutex_);
  errors_.erase(source);
}

void ModuleHealth::addReporter(Reporter reporter) {
  std::lock_guard lock(mutex_);
  reporters_.push_back(std::move(reporter));
}

ModuleStatusInfo ModuleHealth::snapshot() {
  std::vector<Reporter> reporters;
  {
    std::lock_guard lock(mutex_);
    reporters = reporters_;
  }
  for (const Reporter& report : reporters) report(*this);
  std::lock_guard lock(mutex_);
  ModuleStatusInfo copy = status_;
  copy.uptimeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  const bool degraded = std::any_of(errors_.begin(), errors_.end(), [](const auto& e) { return e.second.degrades; });
  if (degraded && copy.state == ModuleRunState::Running) copy.state = ModuleRunState::Degraded;
  std::uint64_t newest = 0;
  for (const auto& [source, entry] : errors_)
    if (entry.order > newest && (entry.degrades || !degraded)) {
      newest = entry.order;
      copy.lastError = source + ": " + entry.message;
    }
  return copy;
}

}  // namespace rgnav
