// One-line text forms of scans and odometry readings, as rgnav-cat prints and records them.
#pragma once

#include <string>

#include "clientlibs/scanmapper/CorrectedScans.h"
#include "core/common/SensorData.h"

namespace rgnav {

// "scan <id> <stamp> <beams> <valid> <no-return> <min> <max> <odom x y theta>"
std::string formatScan(const LaserScan& scan);
// "odom <id> <stamp> <x> <y> <theta> <tv> <rv>"
std::string formatOdometry(const OdometryReading& odometry);
// "corrected <id> <stamp> <x> <y> <theta> <keyframe 0|1>" (the corrected pose in the map frame)
std::string formatCorrected(const CorrectedScan& scan);

inline DataId recordId(const LaserScan& scan) { return scan.id; }
inline DataId recordId(const OdometryReading& odometry) { return odometry.id; }
inline DataId recordId(const CorrectedScan& scan) { return scan.scan.id; }

}  // namespace rgnav
