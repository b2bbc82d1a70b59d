// Plain C++ forms of what the watchdog reports (Watchdog.idl): module process states and events.
#pragma once

#include <cstdint>
#include <string>

#include "core/supervision/ProcessState.h"

namespace rgnav {

const char* toString(ProcessState state);

struct ModuleProcessInfo {
  std::string name;
  ProcessState state = ProcessState::Stopped;
  std::int64_t pid = 0;
  double uptimeSeconds = 0.0;
  std::uint32_t restarts = 0;
  std::string lastEvent;

  friend bool operator==(const ModuleProcessInfo&, const ModuleProcessInfo&) = default;
};

struct SupervisionEvent {
  std::uint64_t id = 0;
  std::string time;  // ISO 8601 UTC
  std::string module;
  std::string what;
  std::string detail;

  friend bool operator==(const SupervisionEvent&, const SupervisionEvent&) = default;
};

}  // namespace rgnav
