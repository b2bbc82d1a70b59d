// openLog: opens a log file with the reader its name calls for: the Intel JSON reader for
// .json / .json.gz / .json.xz, the CARMEN reader for anything else. readLaserScans: the scans of
// such a file, in log order (for the evaluations, which take a log whole).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "core/logs/LogSource.h"

namespace rgnav {

// True for paths ending in .json, .json.gz or .json.xz (letter case ignored).
bool isJsonLogPath(const std::string& path);

// Throws as the chosen reader's constructor does.
std::unique_ptr<LogSource> openLog(const std::string& path, const LogReaderOptions& options = {});

// The first maxScans scans of the log (0: all). Throws as openLog and the reader's next() do,
// and InvalidArgumentError if the log holds no scan.
std::vector<LaserScan> readLaserScans(const std::string& path, const LogReaderOptions& options = {},
                                      std::size_t maxScans = 0);

}  // namespace rgnav
