// OdometryMotion: the decomposition (Probabilistic Robotics, Table 5.6, first three lines) and the
// pose update that inverts it.
#include "core/common/OdometryMotion.h"

#include <cmath>

namespace rgnav {

OdometryMotion decomposeMotion(const Pose2D& from, const Pose2D& to) {
  const double dx = to.x - from.x;
  const double dy = to.y - from.y;
  OdometryMotion m;
  m.trans = std::hypot(dx, dy);
  if (m.trans >= kMinOdometryTranslation) {
    m.rot1 = normalizeAngle(std::atan2(dy, dx) - from.theta);
    if (std::abs(m.rot1) > M_PI / 2.0) {
      m.rot1 = normalizeAngle(m.rot1 + M_PI);
      m.trans = -m.trans;
    }
  } else {
    m.trans = 0.0;
  }
  m.rot2 = normalizeAngle(to.theta - from.theta - m.rot1);
  return m;
}

Pose2D applyMotion(const Pose2D& from, const OdometryMotion& m) {
  const double heading = from.theta + m.rot1;
  return {from.x + m.trans * std::cos(heading), from.y + m.trans * std::sin(heading),
          normalizeAngle(from.theta + m.rot1 + m.rot2)};
}

}  // namespace rgnav
