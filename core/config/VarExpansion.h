// Expands ${NAME} references in config strings from a given variable map.
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace rgnav {

using ConfigVars = std::map<std::string, std::string>;

// Replaces every ${NAME} (NAME = [A-Za-z_][A-Za-z0-9_]*) by its value; a '$' not followed by
// '{' is kept. Throws ConfigError for an unknown variable, a bad name or a missing '}'.
std::string expandVariables(std::string_view text, const ConfigVars& vars);

}  // namespace rgnav
