// Persistence of the replay origin (see PlaybackClock.h).
#include "drivers/carmen/PlaybackClock.h"

#include <filesystem>
#include <fstream>

#include "core/common/AtomicFile.h"

namespace rgnav {

PlaybackClock::PlaybackClock(const std::string& stateDir, const std::string& logPath, const std::string& mode)
    : origin_(std::chrono::system_clock::now()) {
  if (stateDir.empty()) return;
  file_ = stateDir + "/replay-origin";
  const std::string& file = file_;
  const std::string key = logPath + "\n" + mode + "\n";
  std::ifstream in(file);
  std::string savedLog, savedMode;
  long long originNs = 0;
  if (std::getline(in, savedLog) && std::getline(in, savedMode) && (in >> originNs) &&
      savedLog + "\n" + savedMode + "\n" == key) {
    origin_ = std::chrono::system_clock::time_point(
        std::chrono::duration_cast<std::chrono::system_clock::duration>(std::chrono::nanoseconds(originNs)));
    resumed_ = true;
    return;
  }
  const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(origin_.time_since_epoch()).count();
  writeFileAtomically(file, key + std::to_string(ns) + "\n");
}

void PlaybackClock::discard() const {
  if (!file_.empty()) std::filesystem::remove(file_);
}

double PlaybackClock::elapsed() const {
  return std::chrono::duration<double>(std::chrono::system_clock::now() - origin_).count();
}

}  // namespace rgnav
