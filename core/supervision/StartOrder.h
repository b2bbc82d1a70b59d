// Start and stop order of a server set, from the modules' `after` lists.
#pragma once

#include <string>
#include <vector>

#include "core/supervision/SetConfig.h"

namespace rgnav {

// Topological order: every module comes after the modules it names in `after`; among modules
// that could go next, file order wins. Throws ConfigError for a duplicate name, an unknown
// module in `after`, or a cycle (the message lists it: "A -> B -> A").
std::vector<std::string> startOrder(const std::vector<ModuleSpec>& modules);

// The reverse of startOrder.
std::vector<std::string> stopOrder(const std::vector<ModuleSpec>& modules);

}  // namespace rgnav
