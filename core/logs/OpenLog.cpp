// openLog: reader choice by file name.
#include "core/logs/OpenLog.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <string_view>

#include "core/common/Errors.h"

#include "core/logs/CarmenLogReader.h"
#include "core/logs/IntelJsonLogReader.h"

namespace rgnav {

bool isJsonLogPath(const std::string& path) {
  std::string lower(path);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  constexpr std::array<std::string_view, 3> kEndings = {".json", ".json.gz", ".json.xz"};
  return std::any_of(kEndings.begin(), kEndings.end(),
                     [&](std::string_view ending) { return lower.ends_with(ending); });
}

std::unique_ptr<LogSource> openLog(const std::string& path, const LogReaderOptions& options) {
  if (isJsonLogPath(path)) {
    return std::make_unique<IntelJsonLogReader>(path, options);
  }
  return std::make_unique<CarmenLogReader>(path, options);
}

std::vector<LaserScan> readLaserScans(const std::string& path, const LogReaderOptions& options, std::size_t maxScans) {
  const auto log = openLog(path, options);
  const std::size_t limit = maxScans == 0 ? SIZE_MAX : maxScans;
  std::vector<LaserScan> scans;
  while (scans.size() < limit) {
    auto record = log->next();
    if (!record) break;
    if (auto* scan = std::get_if<LaserScan>(&*record)) scans.push_back(std::move(*scan));
  }
  if (scans.empty()) throw InvalidArgumentError("no scans in " + path);
  return scans;
}

}  // namespace rgnav
