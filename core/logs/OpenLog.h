// openLog: opens a log file with the reader its name calls for: the Intel JSON reader for
// .json / .json.gz / .json.xz, the CARMEN reader for anything else.
#pragma once

#include <memory>
#include <string>

#include "core/logs/LogSource.h"

namespace rgnav {

// True for paths ending in .json, .json.gz or .json.xz (letter case ignored).
bool isJsonLogPath(const std::string& path);

// Throws as the chosen reader's constructor does.
std::unique_ptr<LogSource> openLog(const std::string& path, const LogReaderOptions& options = {});

}  // namespace rgnav
