// IntelJsonLogReader: replays the Intel JSON keyframes (data/laser/derived/): for each keyframe, in
// stamp order, an odometry reading with the raw pose, then a laser scan (odometry = raw pose,
// sensorPose = corrected pose, 180° from -90° as FLASER). The corrected-pose file is optional;
// without it sensorPose is the raw pose.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/logs/IntelJsonKeyframes.h"
#include "core/logs/LogSource.h"

namespace rgnav {

class IntelJsonLogReader : public LogSource {
 public:
  // `path`: the raw-odometry file (…_gfs.json.xz); options.correctedPosesPath: the corrected-pose
  // file or empty. Throws FileError if a file cannot be opened, FormatError if one is not the
  // expected JSON or the two files' stamps do not match, InvalidArgumentError for bad options.
  explicit IntelJsonLogReader(const std::string& path, const LogReaderOptions& options = {});

  std::optional<LogRecord> next() override;
  const LogStats& stats() const override { return stats_; }

 private:
  LogStats stats_;
  double maxRange_;
  std::vector<IntelKeyframe> keyframes_;
  std::vector<Pose2D> sensorPoses_;
  std::size_t index_ = 0;
  bool scanPending_ = false;
};

}  // namespace rgnav
