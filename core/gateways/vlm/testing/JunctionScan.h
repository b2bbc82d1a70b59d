// Test helper: noise-free or noisy laser scans of one gateway class, ray cast against the wall
// faces of the simulator's hallway layout (gateway centre at the origin, approach along +x; its
// true gateway points are squareGatewayArea(width)).
#pragma once

#include <vector>

#include "core/common/SensorData.h"
#include "core/gateways/classes/GatewayClass.h"
#include "core/lines/testing/SyntheticScan.h"

namespace rgnav::testing {

// A 180 degree scan, 0.5 degree beams, from `sensorPose` in a hallway of `width` (approach
// hallway 12 m, arms 8 m), with Gaussian range noise of `noiseSigmaM`; `clutter` adds walls
// (e.g. boxWalls) to the layout's.
LaserScan junctionScan(GatewayClass gatewayClass, double width, const Pose2D& sensorPose, double noiseSigmaM = 0.0,
                       unsigned seed = 1, const std::vector<Wall>& clutter = {});

}  // namespace rgnav::testing
