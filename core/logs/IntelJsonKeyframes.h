// IntelJsonKeyframes: loads one file of the Intel JSON pair (data/laser/derived/, plain, gzip or
// xz): {"map": {"<abs ts>": {"range": [...], "x": .., "y": .., "theta": ..}}} as keyframes sorted
// by stamp. Malformed entries are skipped and reported; broken JSON is a FormatError.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/common/SensorData.h"
#include "core/logs/LogStats.h"

namespace rgnav {

struct IntelKeyframe {
  Timestamp stamp = 0.0;
  std::size_t line = 0;        // line of the entry's key in the file
  Pose2D pose;
  std::vector<double> ranges;  // raw beam values
};

struct IntelKeyframeFile {
  std::vector<IntelKeyframe> keyframes;  // strictly increasing stamps
  std::size_t lines = 0;                 // text lines in the file
};

// Decoded files larger than this are refused.
inline constexpr std::size_t kMaxIntelJsonBytes = std::size_t{256} << 20;

// Throws FileError if `path` cannot be opened, FormatError if it is not the expected JSON (line 0
// when the JSON parser cannot say where) or two entries share a stamp. Skipped entries are counted
// into `stats`.
IntelKeyframeFile loadIntelKeyframes(const std::string& path, LogStats& stats);

}  // namespace rgnav
