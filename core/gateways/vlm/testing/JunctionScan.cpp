// Scans of hallway layouts for the VLM tests; see JunctionScan.h.
#include "core/gateways/vlm/testing/JunctionScan.h"

#include "core/sim/scenarios/HallwayLayout.h"

namespace rgnav::testing {

LaserScan junctionScan(GatewayClass gatewayClass, double width, const Pose2D& sensorPose, double noiseSigmaM,
                       unsigned seed, const std::vector<Wall>& clutter) {
  std::vector<Wall> walls = clutter;
  for (const WallFace& f : makeHallwayLayout(gatewayClass, width, 12.0, 8.0).walls)
    walls.push_back({{f.a.x, f.a.y}, {f.b.x, f.b.y}});
  ScanSpec spec;
  spec.noiseSigmaM = noiseSigmaM;
  spec.seed = seed;
  return syntheticScan(walls, sensorPose, spec);
}

}  // namespace rgnav::testing
