// Conversions between GroundTruth.idl types and core types.
#pragma once

#include "GroundTruth.hh"
#include "core/sim/GroundTruth.h"
#include "core/sim/people/Person.h"

namespace rgnav {

RGNav::DoorLine toIdl(const DoorLine& door);
DoorLine fromIdl(const RGNav::DoorLine& door);
RGNav::Person toIdl(const Person& person);
Person fromIdl(const RGNav::Person& person);

}  // namespace rgnav
