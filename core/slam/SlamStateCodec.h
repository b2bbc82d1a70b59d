// SlamState <-> bytes, for the checkpoint the ScanMapper server writes atomically and reloads
// after a restart; and the structural check every restored state must pass. The format is a
// little-endian binary with a magic and version; doubles and floats are stored bit-exactly so a
// restored mapper continues exactly as an uninterrupted one.
#pragma once

#include <string>
#include <string_view>

#include "core/common/Errors.h"
#include "core/slam/SlamState.h"

namespace rgnav {

// Bytes that are not a SlamState of this format: truncated, wrong magic or version, or
// inconsistent content.
class CorruptStateError : public Error {
 public:
  using Error::Error;
};

std::string serializeState(const SlamState& state);

// Throws CorruptStateError naming the byte offset or the inconsistency found.
SlamState deserializeState(std::string_view bytes);

// Throws InvalidArgumentError if the parts do not fit together: scan IDs not increasing,
// keyframe, constraint or submap indices out of range, a keyframe's scan not among the scans.
void validate(const SlamState& state);

}  // namespace rgnav
