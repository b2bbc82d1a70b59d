// LivenessProbe: asks a module whether it is alive (DESIGN.md, supervisors: alive means it
// answers, not that its PID exists). A ping is only asked for; its outcome arrives later as
// Supervisor::onPingResult (answered, or no answer within the heartbeat timeout), so a slow
// module never holds up supervision. The watchdog pings by a remote call on one thread per module
// (watchdog/PingThreads.h); tests answer by hand.
#pragma once

#include <sys/types.h>

#include <string>

namespace rgnav {

class LivenessProbe {
 public:
  virtual ~LivenessProbe() = default;

  // Pings the module's process `pid`: an answer from any other process (one that holds the
  // module's port after a clash) is no answer. Called only while no earlier ping of it is
  // outstanding.
  virtual void ping(const std::string& module, pid_t pid) = 0;
};

}  // namespace rgnav
