// Plain C++ forms of what the ScanMapper module serves (ScanMapper.idl) and its followers read:
// scans with corrected poses (as of the latest revision and as mapped), by ID, with the pose
// graph revision they come from, and the revisions with the scan each was made at.
#pragma once

#include <cstdint>
#include <vector>

#include "core/common/SensorData.h"

namespace rgnav {

struct CorrectedScan {
  LaserScan scan;
  Pose2D corrected;  // as of the latest revision
  Pose2D mapped;     // right after the ScanMapper took the scan in
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

struct PoseRevisionInfo {
  std::uint64_t revision = 0;
  DataId atScan = 0;  // made while this scan was taken in: it revises the scans before it

  friend bool operator==(const PoseRevisionInfo&, const PoseRevisionInfo&) = default;
};

}  // namespace rgnav
