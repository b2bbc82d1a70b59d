// KernelInputs: what the RG Mapping Kernel accepts from its input streams (thesis 5.2: aligned
// scans from the ScanMapper, gateway hypotheses from the GatewayDetection module's buffer), and
// which detector labels are transitions between regions at all. The kernel checks every input
// before it changes anything, so a refused input leaves the map as it was.
#pragma once

#include <string>

#include "core/common/Pose2D.h"
#include "core/gateways/detection/GatewayRecord.h"

namespace rgnav {

// Throws InvalidArgumentError ("<what>: non-finite pose") unless x, y and theta are finite.
void requireFinite(const Pose2D& pose, const std::string& what);

// Throws InvalidArgumentError naming the event and what is wrong: a record without classes, point
// counts that do not fit its kind (narrow passage: 2 gateway and 2 crossing points; hallway area:
// 4 and 4), coinciding gateway points, a non-finite point or pose; for a traversal, sides out of
// range or equal, or a non-finite traversal point or direction.
void validateGatewayEvent(const GatewayEvent& event);

}  // namespace rgnav
