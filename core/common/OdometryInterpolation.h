// interpolateOdometry: the odometry pose at a time stamp, linearly interpolated (angles along
// the shorter arc) between the two readings around it.
#pragma once

#include <deque>
#include <string>

#include "core/common/Errors.h"
#include "core/common/SensorData.h"

namespace rgnav {

// Searches from the newest reading back for two consecutive readings around the stamp, so that
// logs whose stamps occasionally jump backwards (the Intel log repeats poses stamped 0) still
// interpolate between true neighbours. Throws NotAvailableError if no such pair is held.
inline OdometryReading interpolateOdometry(const std::deque<OdometryReading>& readings, Timestamp stamp) {
  for (std::size_t i = readings.size(); i-- > 0;) {
    const OdometryReading& b = readings[i];
    if (b.stamp == stamp) return b;
    if (i == 0 || b.stamp < stamp) continue;
    const OdometryReading& a = readings[i - 1];
    if (a.stamp > stamp) continue;
    const double f = (stamp - a.stamp) / (b.stamp - a.stamp);
    OdometryReading out = a;
    out.stamp = stamp;
    out.pose.x = a.pose.x + f * (b.pose.x - a.pose.x);
    out.pose.y = a.pose.y + f * (b.pose.y - a.pose.y);
    out.pose.theta = normalizeAngle(a.pose.theta + f * normalizeAngle(b.pose.theta - a.pose.theta));
    out.translationalVelocity = a.translationalVelocity + f * (b.translationalVelocity - a.translationalVelocity);
    out.rotationalVelocity = a.rotationalVelocity + f * (b.rotationalVelocity - a.rotationalVelocity);
    return out;
  }
  throw NotAvailableError("no odometry around stamp " + std::to_string(stamp) +
                          (readings.empty() ? std::string(" (none held)")
                                            : " (held: " + std::to_string(readings.front().stamp) + ".." +
                                                  std::to_string(readings.back().stamp) + ")"));
}

}  // namespace rgnav
