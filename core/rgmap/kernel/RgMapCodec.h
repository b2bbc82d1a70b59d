// The RG Mapping Kernel's checkpoint: its whole state (RgMapState.h) as versioned JSON
// ({"format": "rgnav-rg-map", "version": 2, ...}). The RGMappingKernel server writes it after
// every change and resumes from it (with lastScanId and lastGatewayEventId it knows where to go
// on in its input streams); a resumed kernel goes on exactly as if it had not stopped, and the
// same state always gives the same bytes.
// Numbers: doubles in the shortest form that reads back to the same double; laser ranges in the
// shortest form that reads back to the same float (at most 9 significant digits instead of 17;
// centimetre ranges take 4 or 5 characters); non-finite values as "inf", "-inf" and null (NaN).
// Scans are the bulk of a checkpoint: 2 to 4 kB per 361-beam scan, so a checkpoint grows with
// the scans the map holds.
#pragma once

#include <string>

#include "core/rgmap/kernel/RgMapState.h"

namespace rgnav {

std::string serializeRgMap(const RgMapState& state);

// Throws FormatError (file "<checkpoint>", line 0) for anything that is not a checkpoint of this
// format and version, including a state that fails checkConsistency (RgMapConsistency.h) or holds
// learned costs the cost table refuses.
RgMapState deserializeRgMap(const std::string& text);

}  // namespace rgnav
