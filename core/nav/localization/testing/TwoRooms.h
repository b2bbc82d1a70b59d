// TwoRooms: a small RG map for the localization tests: two 4 m x 4 m rooms side by side, joined
// by a 0.8 m door in the wall x = 4 (map frame). Region 1 has the identity frame; region 2's frame
// is rotated and shifted, so hand-over has a real transform to apply. simulatedScan ray-casts a
// scan against the true walls.
#pragma once

#include <vector>

#include "core/common/SensorData.h"
#include "core/rgmap/kernel/RgMapViews.h"

namespace rgnav::testing {

struct TwoRooms {
  std::vector<RegionView> regions;
  std::vector<GatewayView> gateways;
  std::vector<Segment2> walls;  // map frame
};

TwoRooms twoRooms();

// 181 beams over [-pi/2, pi/2], max range 10 m, no noise; scan.odometry = `odometry`.
LaserScan simulatedScan(const std::vector<Segment2>& walls, const Pose2D& truth, const Pose2D& odometry, DataId id);

}  // namespace rgnav::testing
