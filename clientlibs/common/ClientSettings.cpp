// Reads client settings from the environment and parses naming endpoints.
#include "clientlibs/common/ClientSettings.h"

#include <cstdlib>

#include "core/common/Errors.h"
#include "core/common/HostPort.h"

namespace rgnav {

ClientSettings ClientSettings::fromEnvironment() {
  ClientSettings settings;
  if (const char* naming = std::getenv("RGNAV_NAMING"); naming && *naming) settings.setNaming(naming);
  if (const char* robot = std::getenv("RGNAV_ROBOT"); robot && *robot) settings.robot = robot;
  return settings;
}

void ClientSettings::setNaming(const std::string& hostPort) {
  const HostPort hp = parseHostPort(hostPort);
  namingHost = hp.host;
  namingPort = hp.port;
}

}  // namespace rgnav
