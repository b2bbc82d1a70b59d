// LogCompleteness: the Laser module's log counters read into a verdict (see LogCompleteness.h).
#include "tools/rgmap/LogCompleteness.h"

#include "clientlibs/laser/LaserClient.h"
#include "core/common/Errors.h"

namespace rgnav {

LogCompleteness laserLogCompleteness(ClientSettings settings) {
  settings.retryBudget = std::chrono::seconds(5);
  ModuleStatusInfo status;
  try {
    status = LaserClient(settings).status();
  } catch (const std::exception& e) {
    throw Error(std::string("cannot tell whether the map is of the whole log: no status from the Laser module: ") +
                e.what());
  }
  const auto skipped = status.counters.find("log_skipped_lines");
  const auto truncated = status.counters.find("log_truncated");
  LogCompleteness verdict;
  if (skipped == status.counters.end() || truncated == status.counters.end()) return verdict;
  verdict.fromLog = true;
  verdict.whole = skipped->second == 0 && truncated->second == 0;
  verdict.figures = "skipped_lines=" + std::to_string(skipped->second) +
                    " truncated=" + (truncated->second != 0 ? "yes" : "no");
  if (!verdict.whole) verdict.problem = status.lastError;
  return verdict;
}

}  // namespace rgnav
