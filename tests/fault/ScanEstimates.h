// ScanEstimates: the estimate the localization fault test (issue 28, `rgctl faulttest
// localization`) scores for every scan of the run: the first one the Localization module served
// for the scan, or - for a scan it never served one for (taken by a process that was killed before
// the estimate was fetched, and skipped by the restarted process, which resumed from a checkpoint
// after it) - the estimate of the scan before moved on by the raw odometry in between, as the
// module itself moves an estimate on between its filter updates.
#pragma once

#include <cstddef>
#include <map>
#include <span>
#include <vector>

#include "tests/fault/AnchoredRun.h"

namespace rgnav::testing {

struct ScanEstimates {
  std::vector<Pose2D> estimates;  // per scan of `scans`
  std::size_t propagated = 0;     // of them moved on by the odometry
};

// std::runtime_error when the first scan has no served estimate (nothing to move on from).
ScanEstimates estimatesOfEveryScan(std::span<const AnchoredScan> scans, const std::map<DataId, Pose2D>& served);

}  // namespace rgnav::testing
