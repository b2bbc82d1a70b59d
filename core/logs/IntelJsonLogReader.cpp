// IntelJsonLogReader: pairs raw and corrected keyframes by stamp and hands them out as records.
#include "core/logs/IntelJsonLogReader.h"

#include <cmath>

#include "core/common/Errors.h"
#include "core/logs/FlaserGeometry.h"
#include "core/logs/RangeSanitizer.h"

namespace rgnav {

namespace {

// Stamps are written with microseconds; closer than this they name the same keyframe.
constexpr double kStampTolerance = 1e-6;

std::string stampText(Timestamp stamp) { return std::to_string(stamp); }

// The corrected pose of every raw keyframe, matched by stamp.
std::vector<Pose2D> matchCorrected(const std::vector<IntelKeyframe>& raw,
                                   const std::string& correctedPath, LogStats& stats) {
  const IntelKeyframeFile corrected = loadIntelKeyframes(correctedPath, stats);
  stats.lines += corrected.lines;
  const auto& keyframes = corrected.keyframes;
  std::vector<Pose2D> poses;
  poses.reserve(raw.size());
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (i == keyframes.size()) {
      throw FormatError(correctedPath, corrected.lines,
                        "no keyframe for raw stamp " + stampText(raw[i].stamp));
    }
    if (std::abs(keyframes[i].stamp - raw[i].stamp) > kStampTolerance) {
      throw FormatError(correctedPath, keyframes[i].line,
                        "keyframe stamp " + stampText(keyframes[i].stamp) +
                            " does not match raw keyframe stamp " + stampText(raw[i].stamp));
    }
    poses.push_back(keyframes[i].pose);
  }
  if (keyframes.size() > raw.size()) {
    throw FormatError(correctedPath, keyframes[raw.size()].line,
                      "keyframe stamp " + stampText(keyframes[raw.size()].stamp) +
                          " has no raw keyframe");
  }
  return poses;
}

}  // namespace

IntelJsonLogReader::IntelJsonLogReader(const std::string& path, const LogReaderOptions& options)
    : maxRange_(options.maxRange) {
  validate(options);
  IntelKeyframeFile raw = loadIntelKeyframes(path, stats_);
  stats_.lines = raw.lines;
  keyframes_ = std::move(raw.keyframes);
  if (options.correctedPosesPath.empty()) {
    for (const auto& keyframe : keyframes_) {
      sensorPoses_.push_back(keyframe.pose);
    }
  } else {
    sensorPoses_ = matchCorrected(keyframes_, options.correctedPosesPath, stats_);
  }
}

std::optional<LogRecord> IntelJsonLogReader::next() {
  if (index_ == keyframes_.size()) {
    return std::nullopt;
  }
  IntelKeyframe& keyframe = keyframes_[index_];
  const DataId id = index_ + 1;
  if (!scanPending_) {
    scanPending_ = true;
    ++stats_.odometryReadings;
    OdometryReading reading;
    reading.id = id;
    reading.stamp = keyframe.stamp;
    reading.pose = keyframe.pose;
    return reading;
  }
  scanPending_ = false;
  ++index_;
  ++stats_.scans;
  LaserScan scan;
  scan.id = id;
  scan.stamp = keyframe.stamp;
  scan.odometry = keyframe.pose;
  scan.sensorPose = sensorPoses_[id - 1];
  scan.startAngle = kFlaserStartAngle;
  scan.angleIncrement = flaserAngleIncrement(keyframe.ranges.size());
  scan.maxRange = maxRange_;
  sanitizeRanges(keyframe.ranges, maxRange_, scan.ranges, stats_);
  keyframe.ranges = {};
  return scan;
}

}  // namespace rgnav
