// Plain C++ forms of what the ScanMapper module serves (ScanMapper.idl): scans with corrected
// poses, by ID, with the pose graph revision they come from.
#pragma once

#include <cstdint>
#include <vector>

#include "core/common/SensorData.h"

namespace rgnav {

struct CorrectedScan {
  LaserScan scan;
  Pose2D corrected;
  bool keyframe = false;

  friend bool operator==(const CorrectedScan&, const CorrectedScan&) = default;
};

struct CorrectedBatch {
  std::vector<CorrectedScan> scans;
  DataId latestId = 0;
  std::uint64_t revision = 0;
  bool endOfData = false;
};

struct PoseUpdate {
  DataId id = 0;
  Pose2D corrected;

  friend bool operator==(const PoseUpdate&, const PoseUpdate&) = default;
};

}  // namespace rgnav
