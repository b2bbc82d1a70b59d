// One-line text forms of scans and odometry readings, as rgnav-cat prints and records them.
#pragma once

#include <string>

#include "core/common/SensorData.h"

namespace rgnav {

// "scan <id> <stamp> <beams> <valid> <no-return> <min> <max> <odom x y theta>"
std::string formatScan(const LaserScan& scan);
// "odom <id> <stamp> <x> <y> <theta> <tv> <rv>"
std::string formatOdometry(const OdometryReading& odometry);

}  // namespace rgnav
