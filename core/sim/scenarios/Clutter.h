// Clutter: people, flower pots and boxes placed at random in a hallway layout, for the
// uncluttered / slightly / strongly cluttered environments of thesis 4.1.4 (figure 4.8). Objects
// stand against the wall faces (up to 0.1 m away); at the strong level there are more and larger
// ones, and people also stand in the middle of the hallways. Every object keeps 0.1 m from the
// others and out of a rectangle that must stay clear (the robot's approach lanes). Seeded
// std::mt19937_64; objects that find no valid place in a bounded number of draws are left out,
// deterministically.
#pragma once

#include <random>
#include <string_view>
#include <vector>

#include "core/raster/OccupancyGrid.h"
#include "core/sim/scenarios/GridDrawing.h"
#include "core/sim/scenarios/HallwayLayout.h"

namespace rgnav {

enum class ClutterLevel { None, Slight, Strong };

std::string_view clutterLevelName(ClutterLevel level);  // "uncluttered", "slightly cluttered", ...

enum class ClutterKind { Person, FlowerPot, Box };

struct ClutterObject {
  ClutterKind kind = ClutterKind::Box;
  WorldPoint centre;
  double halfX = 0.0;  // m; for people and pots (discs) halfX = halfY = radius
  double halfY = 0.0;
};

std::vector<ClutterObject> placeClutter(const HallwayLayout& layout, ClutterLevel level,
                                        const WorldRect& keepClear, std::mt19937_64& rng);

void drawClutter(OccupancyGrid& grid, const std::vector<ClutterObject>& objects);

}  // namespace rgnav
