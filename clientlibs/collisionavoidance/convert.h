// Conversions between CollisionAvoidance.idl types and the module's plain types (DriveProgress.h):
// drive states and the drive's status. Goals and target poses convert as the PathPlanning
// module's (clientlibs/pathplanning/convert.h).
#pragma once

#include "CollisionAvoidance.hh"
#include "core/nav/avoidance/DriveProgress.h"

namespace rgnav {

RGNav::AvoidanceState toIdl(DrivePhase phase);
DrivePhase fromIdl(RGNav::AvoidanceState state);  // InvalidArgumentError for an unknown state
RGNav::AvoidanceStatus toIdl(const DriveProgress& progress);
DriveProgress fromIdl(const RGNav::AvoidanceStatus& info);

}  // namespace rgnav
