// ModuleHealth: a server's self-description for Service::status(): state, uptime, counters and
// the last error. Errors are kept per source ("naming", "log", ...) so that a source can clear
// its own once the problem is gone; reporters are asked at every snapshot, so status() is
// current whichever call last touched the module. An error set with setDegraded (a module that
// lives but cannot do all of its job, e.g. cannot write its checkpoints) makes a running module
// DEGRADED, with that error as lastError, until its source clears it. Thread-safe.
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
  // An error that degrades the module (see above); clearError ends it.
  void setDegraded(const std::string& source, const std::string& reason);
  void clearError(const std::string& source);
  void addReporter(Reporter reporter);
  // lastError is the most recent error that is not cleared, as "source: message"; while any
  // error degrades the module, the most recent of those.
  ModuleStatusInfo snapshot();

 private:
  std::mutex mutex_;
  const std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  ModuleStatusInfo status_;
  struct Error {
    std::uint64_t order = 0;
    std::string message;
    bool degrades = false;
  };
  void record(const std::string& source, const std::string& message, bool degrades);  // under lock

  std::map<std::string, Error> errors_;  // by source
  std::uint64_t errorOrder_ = 0;
  std::vector<Reporter> reporters_;
};

}  // namespace rgnav
