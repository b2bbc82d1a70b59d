// Whose motion made a contact (see ContactBlame.h).
#include "core/sim/people/ContactBlame.h"

#include <cmath>

namespace rgnav {

bool robotDroveInto(const Footprint& footprint, const Pose2D& robot, double velocity, double rotational,
                    const WorldPoint& person) {
  // The contact point, and the direction from it to the person (from the centre if the person's
  // centre is inside the outline).
  const WorldPoint q = footprint.nearestPoint(robot, person);
  double nx = person.x - q.x, ny = person.y - q.y;
  if (std::hypot(nx, ny) < 1e-9) {
    nx = person.x - robot.x;
    ny = person.y - robot.y;
  }
  const double norm = std::hypot(nx, ny);
  if (norm < 1e-9) return std::abs(velocity) > kContactApproachSpeed;
  // The contact point's velocity: the translation plus the rotation about the rotation centre.
  const double rx = q.x - robot.x, ry = q.y - robot.y;
  const double vx = velocity * std::cos(robot.theta) - rotational * ry;
  const double vy = velocity * std::sin(robot.theta) + rotational * rx;
  return (vx * nx + vy * ny) / norm > kContactApproachSpeed;
}

}  // namespace rgnav
