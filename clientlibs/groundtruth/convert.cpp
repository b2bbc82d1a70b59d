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

RGNav::Person toIdl(const Person& person) {
  return RGNav::Person{person.position.x, person.position.y, person.velocity.x, person.velocity.y, person.radius};
}

Person fromIdl(const RGNav::Person& person) {
  return Person{WorldPoint{person.x, person.y}, WorldPoint{person.vx, person.vy}, person.radius};
}

}  // namespace rgnav
