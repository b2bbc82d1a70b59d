// ToolClient: how a command-line tool reaches the modules of a set: client settings from the
// environment and its --naming/--robot options with the short first contact (a set that is not
// up is reported within 2 s, not waited out like a restart), and what it tells the user when a
// module does not answer.
#pragma once

#include <iostream>
#include <string>

#include "clientlibs/common/ClientConnection.h"
#include "clientlibs/common/ClientSettings.h"

namespace rgnav {

// RGNAV_NAMING/RGNAV_ROBOT, overridden by non-empty naming ("host:port") and robot options.
inline ClientSettings toolClientSettings(const std::string& naming, const std::string& robot) {
  ClientSettings settings = ClientSettings::fromEnvironment();
  if (!naming.empty()) settings.setNaming(naming);
  if (!robot.empty()) settings.robot = robot;
  settings.firstContactBudget = kToolFirstContactBudget;
  return settings;
}

// Prints the error (which names the address and object tried) and what the user can do.
inline void reportUnreachable(const char* tool, const ModuleUnavailableError& e, bool viaNaming) {
  std::cerr << tool << ": " << e.what() << "\n"
            << tool << ": is the set up? `rgctl status <set>` tells, `rgctl up <set>` starts it";
  if (viaNaming)
    std::cerr << "; the tool finds the set through its naming service: --naming host:port or RGNAV_NAMING "
                 "(`rgnav-ctl --set <set file> naming` prints it)";
  std::cerr << std::endl;
}

}  // namespace rgnav
