// Conversions between GroundTruth.idl types and core types (see convert.h).
#include "clientlibs/groundtruth/convert.h"

namespace rgnav {

RGNav::DoorLine toIdl(const DoorLine& door) {
  return RGNav::DoorLine{RGNav::Pose2D{door.a.x, door.a.y, 0.0}, RGNav::Pose2D{door.b.x, door.b.y, 0.0}, door.roomA,
                         door.roomB};
}

DoorLine fromIdl(const RGNav::DoorLine& door) {
  return DoorLine{WorldPoint{door.a.x, door.a.y}, WorldPoint{door.b.x, door.b.y}, door.roomA, door.roomB};
}

}  // namespace rgnav
