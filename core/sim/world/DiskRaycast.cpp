// castToDisk: the nearer root of |from + t * direction - centre| = radius (see DiskRaycast.h).
#include "core/sim/world/DiskRaycast.h"

#include <cmath>
#include <limits>

namespace rgnav {

double castToDisk(WorldPoint from, double angle, const DiskObstacle& disk) {
  const double mx = from.x - disk.centre.x, my = from.y - disk.centre.y;
  const double c = mx * mx + my * my - disk.radius * disk.radius;
  if (c <= 0.0) return 0.0;
  const double b = mx * std::cos(angle) + my * std::sin(angle);
  const double discriminant = b * b - c;
  // Outside the disk both roots have the same sign: a hit needs them ahead (b < 0) and real.
  if (b >= 0.0 || discriminant <= 0.0) return std::numeric_limits<double>::infinity();
  return -b - std::sqrt(discriminant);
}

}  // namespace rgnav
