// HallwayLayout: the geometry of one gateway of thesis 4.1.4 in a frame where the gateway centre
// is the origin and the robot approaches along +x: an approach hallway from behind, the square
// gateway area (side = hallway width) and the hallways that leave it to the left (+y), straight
// on (+x) and to the right (-y) as the class says (GatewayClass openings), each ending in a wall.
// Also lists the inner faces of the walls (for placing clutter against them) and rasterises the
// layout into an OccupancyGrid with solid walls around it.
#pragma once

#include <vector>

#include "core/gateways/classes/GatewayClass.h"
#include "core/raster/OccupancyGrid.h"
#include "core/sim/scenarios/GridDrawing.h"

namespace rgnav {

struct WallFace {
  WorldPoint a;
  WorldPoint b;
  WorldPoint inward;  // unit normal pointing into the hallway
};

struct HallwayLayout {
  GatewayClass gatewayClass = GatewayClass::Hallway;
  double width = 0.0;                // m
  std::vector<WorldRect> hallways;   // free space: approach hallway, gateway area, open hallways
  std::vector<WallFace> walls;       // inner wall faces
};

// `approachLength`: length of the approach hallway before the gateway area; `armLength`: length
// of each hallway leaving it. Throws ConfigError for non-positive lengths.
HallwayLayout makeHallwayLayout(GatewayClass gatewayClass, double width, double approachLength,
                                double armLength);

// The layout as a grid: free hallways, everything else occupied, with `wallThickness` of
// occupied cells around the free space.
OccupancyGrid rasterize(const HallwayLayout& layout, double resolution, double wallThickness);

// Whether `p` lies in the layout's free space.
bool insideHallways(const HallwayLayout& layout, WorldPoint p);

}  // namespace rgnav
