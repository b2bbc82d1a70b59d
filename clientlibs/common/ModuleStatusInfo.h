// ModuleStatusInfo: the plain C++ form of a module's status (Module.idl ModuleStatus), shared by
// servers that report it and clients that read it.
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace rgnav {

enum class ModuleRunState { Starting, Running, Degraded, Stopping };

struct ModuleStatusInfo {
  std::string name;
  ModuleRunState state = ModuleRunState::Starting;
  std::uint32_t pid = 0;
  double uptimeSeconds = 0.0;
  std::map<std::string, std::uint64_t> counters;
  std::string lastError;

  friend bool operator==(const ModuleStatusInfo&, const ModuleStatusInfo&) = default;
};

const char* toString(ModuleRunState state);

}  // namespace rgnav
