// Identity of a running module process: PID plus start time, which together survive PID reuse.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>

namespace rgnav {

struct ProcessRecord {
  std::string module;
  pid_t pid = 0;
  std::uint64_t startTime = 0;  // /proc/<pid>/stat field 22

  bool operator==(const ProcessRecord&) const = default;
};

}  // namespace rgnav
