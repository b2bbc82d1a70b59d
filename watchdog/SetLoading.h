// loadSet: reads a server-set file the way every RG Nav program does, with ${RGNAV_BIN},
// ${RGNAV_ROOT} and ${RGNAV_SHARED} taken from the environment or derived from where the
// program and the project lie.
#pragma once

#include <string>

#include "core/supervision/SetConfig.h"

namespace rgnav {

// The project root: RGNAV_ROOT, else the working directory.
std::string defaultProjectRoot();

// root: base for a relative run_dir and the value of ${RGNAV_ROOT}.
SetConfig loadSet(const std::string& setFile, const std::string& root);

}  // namespace rgnav
