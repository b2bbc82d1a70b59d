// interpolateOdometry: the odometry pose at a time stamp, linearly interpolated (angles along
// the shorter arc) between the two readings around it.
#pragma once

#include <algorithm>
#include <deque>
#include <string>

#include "core/common/Errors.h"
#include "core/common/SensorData.h"

namespace rgnav {

// `readings` ordered by stamp. Throws NotAvailableError outside their span.
inline OdometryReading interpolateOdometry(const std::deque<OdometryReading>& readings, Timestamp stamp) {
  if (readings.empty() || stamp < readings.front().stamp || stamp > readings.back().stamp)
    throw NotAvailableError("no odometry around stamp " + std::to_string(stamp) +
                            (readings.empty() ? std::string(" (none held)")
                                              : " (held: " + std::to_string(readings.front().stamp) + ".." +
                                                    std::to_string(readings.back().stamp) + ")"));
  const auto after = std::lower_bound(readings.begin(), readings.end(), stamp,
                                      [](const OdometryReading& r, Timestamp t) { return r.stamp < t; });
  if (after->stamp == stamp || after == readings.begin()) return *after;
  const OdometryReading& a = *std::prev(after);
  const OdometryReading& b = *after;
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

}  // namespace rgnav
