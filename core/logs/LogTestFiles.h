// Test helpers for the log readers: a temporary folder removed afterwards, writers for plain,
// gzip and xz files, paths into the shared data folder (${RGNAV_SHARED}) and a collector of all
// records of a log.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/logs/LogSource.h"

namespace rgnav::testing {

// A fresh folder made with mkdtemp; it and its contents are removed on destruction.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  // The path of `name` inside the folder.
  std::string file(const std::string& name) const;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

void writeFile(const std::string& path, std::string_view bytes);
std::string gzipCompress(std::string_view bytes);
std::string xzCompress(std::string_view bytes);
// `size` pseudo-random bytes, the same for the same seed.
std::string randomBytes(std::size_t size, unsigned seed);

// ${RGNAV_SHARED}/data/<relative>, with ../shared (beside the project root) if unset.
std::string sharedData(const std::string& relative);

// Everything a log source yields, and its final statistics.
struct LogContents {
  std::vector<LaserScan> scans;
  std::vector<OdometryReading> odometry;
  std::vector<LogRecord> records;  // both kinds, in the order read
  LogStats stats;
};
LogContents readAll(LogSource& source);

}  // namespace rgnav::testing
