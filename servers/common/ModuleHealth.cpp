// ModuleHealth bookkeeping (see ModuleHealth.h).
#include "servers/common/ModuleHealth.h"

#include <unistd.h>

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

void ModuleHealth::setError(const std::string& message) {
  std::lock_guard lock(mutex_);
  status_.lastError = message;
}

ModuleStatusInfo ModuleHealth::snapshot() const {
  std::lock_guard lock(mutex_);
  ModuleStatusInfo copy = status_;
  copy.uptimeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  return copy;
}

}  // namespace rgnav
