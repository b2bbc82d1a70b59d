// ModuleHealth: a server's self-description for Service::status(): state, uptime, counters and
// the last error. Errors are kept per source ("naming", "log", ...) so that a source can clear
// its own once the problem is gone; reporters are asked at every snapshot, so status() is
// current whichever call last touched the module. Thread-safe.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "clientlibs/common/ModuleStatusInfo.h"

namespace rgnav {

class ModuleHealth {
 public:
  // Fills counters and errors of a snapshot from a module's own bookkeeping.
  using Reporter = std::function<void(ModuleHealth&)>;

  ModuleHealth();

  void setName(const std::string& name);
  void setState(ModuleRunState state);
  void add(const std::string& counter, std::uint64_t amount = 1);
  void set(const std::string& counter, std::uint64_t value);
  void setError(const std::string& source, const std::string& message);
  void clearError(const std::string& source);
  void addReporter(Reporter reporter);
  // lastError is the most recent error that is not cleared, as "source: message".
  ModuleStatusInfo snapshot();

 private:
  std::mutex mutex_;
  const std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  ModuleStatusInfo status_;
  std::map<std::string, std::pair<std::uint64_t, std::string>> errors_;  // source -> (order, message)
  std::uint64_t errorOrder_ = 0;
  std::vector<Reporter> reporters_;
};

}  // namespace rgnav
