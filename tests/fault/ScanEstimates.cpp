// Every scan's scored estimate: served, or moved on by the odometry (see ScanEstimates.h).
#include "tests/fault/ScanEstimates.h"

#include <stdexcept>

namespace rgnav::testing {

ScanEstimates estimatesOfEveryScan(std::span<const AnchoredScan> scans, const std::map<DataId, Pose2D>& served) {
  ScanEstimates out;
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const auto found = served.find(scans[i].id);
    if (found != served.end()) {
      out.estimates.push_back(found->second);
      continue;
    }
    if (i == 0) throw std::runtime_error("the module served no estimate of the first scan: it did not start there");
    out.estimates.push_back(compose(out.estimates.back(), between(scans[i - 1].odometry, scans[i].odometry)));
    ++out.propagated;
  }
  return out;
}

}  // namespace rgnav::testing
