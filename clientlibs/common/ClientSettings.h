// ClientSettings: where to find the naming service and how patiently to talk to modules.
#pragma once

#include <chrono>
#include <optional>
#include <string>

namespace rgnav {

// The first-contact budget of the command-line tools: they answer within 2 s either way.
inline constexpr std::chrono::milliseconds kToolFirstContactBudget{1500};

struct ClientSettings {
  std::string namingHost = "127.0.0.1";
  int namingPort = 2809;
  std::string robot = "tumbot";
  std::string consumer;  // who asks for data by ID (module or program name); "" is anonymous
  std::chrono::milliseconds callTimeout{2000};     // one call, answer included
  std::chrono::milliseconds connectTimeout{500};   // opening a connection
  std::chrono::milliseconds retryBudget{15000};    // retries of one call, then the module is down
  // Until the module has been reached once, give up after this instead of retryBudget (unset: the
  // same budget). A command-line tool sets it short (kToolFirstContactBudget): a set that is not
  // up, or a wrong naming address, is reported at once instead of waited out like a restart.
  std::optional<std::chrono::milliseconds> firstContactBudget;
  std::chrono::milliseconds backoffInitial{10};
  std::chrono::milliseconds backoffMax{200};

  // Defaults overridden by RGNAV_NAMING ("host:port") and RGNAV_ROBOT when set.
  static ClientSettings fromEnvironment();
  // Parses "host:port"; throws ConfigError.
  void setNaming(const std::string& hostPort);
};

}  // namespace rgnav
