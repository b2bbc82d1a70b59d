// Where the project's shipped config files are for programs started by tests, evaluations and
// rgctl: under $RGNAV_ROOT/config (rgctl and CTest set it), else under config/ of the working
// directory.
#pragma once

#include <string>

namespace rgnav {

// The absolute path of config/<relative>, e.g. shippedConfigFile("modules/scanmapper.yaml").
std::string shippedConfigFile(const std::string& relative);

}  // namespace rgnav
