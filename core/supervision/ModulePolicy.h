// Restart policy and timeouts of one supervised module, as read from a server-set file.
#pragma once

#include <chrono>
#include <optional>
#include <string_view>

namespace rgnav {

// Erlang/OTP meaning: permanent modules are always restarted, transient ones only after an
// abnormal exit, temporary ones never.
enum class RestartPolicy { Permanent, Transient, Temporary };

std::optional<RestartPolicy> parseRestartPolicy(std::string_view text);
const char* toString(RestartPolicy policy);

struct ModulePolicy {
  RestartPolicy restart = RestartPolicy::Permanent;
  int maxRestarts = 10;  // at most this many restarts ...
  std::chrono::nanoseconds restartWindow = std::chrono::seconds(60);  // ... within this window
  std::chrono::nanoseconds backoffInitial = std::chrono::milliseconds(50);
  std::chrono::nanoseconds backoffMax = std::chrono::seconds(2);
  std::chrono::nanoseconds startTimeout = std::chrono::seconds(10);  // until the first answered ping
  std::chrono::nanoseconds stopTimeout = std::chrono::seconds(3);    // SIGTERM, then SIGKILL
};

// How long a stop still waits for the exit after SIGKILL before it gives the process up.
inline constexpr std::chrono::seconds kKillGrace{5};

}  // namespace rgnav
