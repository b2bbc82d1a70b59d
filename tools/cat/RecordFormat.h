// One-line text forms of scans and odometry readings, as rgnav-cat prints and records them.
#pragma once

#include <string>

#include "core/gateways/detection/GatewayEventBatch.h"
#include "core/slam/CorrectedScans.h"
#include "core/common/SensorData.h"

namespace rgnav {

// "scan <id> <stamp> <beams> <valid> <no-return> <min> <max> <odom x y theta>"
std::string formatScan(const LaserScan& scan);
// "odom <id> <stamp> <x> <y> <theta> <tv> <rv>"
std::string formatOdometry(const OdometryReading& odometry);
// "corrected <id> <stamp> <x> <y> <theta> <keyframe 0|1>" (the corrected pose in the map frame)
std::string formatCorrected(const CorrectedScan& scan);
// "gateway <event id> scan=<id> detected|updated|traversed <gateway id> <label> <p> width=<m>
//  points=<x>,<y>;... seen=<first>-<last> [from=<side> to=<side> at=<x>,<y>]" (odometry frame)
std::string formatGatewayEvent(const GatewayEvent& event);
// "<gateway id> <label> <p> width=<m> points=... seen=<first>-<last> support=<n> traversals=<n>"
std::string formatGateway(const GatewayRecord& gateway);

inline DataId recordId(const LaserScan& scan) { return scan.id; }
inline DataId recordId(const OdometryReading& odometry) { return odometry.id; }
inline DataId recordId(const CorrectedScan& scan) { return scan.scan.id; }
inline DataId recordId(const GatewayEvent& event) { return event.id; }

}  // namespace rgnav
