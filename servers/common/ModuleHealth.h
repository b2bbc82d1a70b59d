// ModuleHealth: a server's self-description for Service::status(): state, uptime, counters and
// the last error. Thread-safe; servants update it while the ORB serves calls.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>

#include "clientlibs/common/ModuleStatusInfo.h"

namespace rgnav {

class ModuleHealth {
 public:
  ModuleHealth();

  void setName(const std::string& name);

  void setState(ModuleRunState state);
  void add(const std::string& counter, std::uint64_t amount = 1);
  void set(const std::string& counter, std::uint64_t value);
  void setError(const std::string& message);
  ModuleStatusInfo snapshot() const;

 private:
  mutable std::mutex mutex_;
  const std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  ModuleStatusInfo status_;
};

}  // namespace rgnav
