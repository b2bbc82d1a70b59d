// The GatewayDetection module's checkpoint: the detector's whole state (GatewayDetector.h) and
// the event buffer, as versioned JSON ({"format": "rgnav-gateway-detection", "version": 3, ...};
// version 2 added the coasted observations of running sequences, version 3 the superseded flag of
// passage tracks; a version 2 checkpoint still reads, with no track superseded).
// Numbers are written in the shortest form that reads back to the same double, so a module that
// resumes from a checkpoint goes on bit for bit as if it had not stopped.
#pragma once

#include <string>
#include <vector>

#include "core/gateways/detection/GatewayDetector.h"

namespace rgnav {

struct DetectionCheckpoint {
  GatewayDetectorState detector;
  std::vector<GatewayEvent> events;  // the buffer, oldest first
};

std::string serializeDetection(const DetectionCheckpoint& checkpoint);

// Throws FormatError (file "<checkpoint>", line 0) for anything that is not a checkpoint of
// this format and version 2 or 3.
DetectionCheckpoint deserializeDetection(const std::string& text);

}  // namespace rgnav
