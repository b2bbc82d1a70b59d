// StampedPoses: the corrected poses of a run taken from another file of the same run (the Intel
// JSON companion `…_corrected_log.json.xz`, a CARMEN corrected log) and matched to a log's scans
// by timestamp, for the localization evaluation (issue 28, "rgctl eval localization"): a scan
// takes the pose whose stamp (plus an offset, for files that count time from another origin) is
// nearest to its own, if within a tolerance (1 ms by default); a scan without one is left out.
// Not read: GMapping's own .gfs output (its corrected trajectory is a particle's ancestry,
// written as resampling indices); convert it to a CARMEN log (gfs2log) first.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/common/SensorData.h"

namespace rgnav {

struct StampedPose {
  Timestamp stamp = 0.0;
  Pose2D pose;
};

// The pose each scan of a log file was taken at as the file gives it (LaserScan::sensorPose:
// the corrected pose in corrected logs), in stamp order. Throws what openLog and the readers
// throw; InvalidArgumentError if the file holds no scan.
std::vector<StampedPose> readScanPoses(const std::string& path);

struct PoseMatch {
  std::vector<std::optional<Pose2D>> poses;  // per scan, in the scans' order
  std::size_t matched = 0;
};

// For each scan the pose of `poses` (ascending stamps) whose stamp + offsetS is nearest to the
// scan's stamp, if at most toleranceS away.
PoseMatch matchByStamp(std::span<const LaserScan> scans, std::span<const StampedPose> poses, double offsetS,
                       double toleranceS);

}  // namespace rgnav
