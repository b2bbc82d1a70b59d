// Conversions between GroundTruth.idl types and core types.
#pragma once

#include "GroundTruth.hh"
#include "core/sim/GroundTruth.h"

namespace rgnav {

RGNav::DoorLine toIdl(const DoorLine& door);
DoorLine fromIdl(const RGNav::DoorLine& door);

}  // namespace rgnav
