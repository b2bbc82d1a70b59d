// MovingAiMap: the MovingAI grid benchmark's files (../shared/data/planning/movingai/SOURCES.md):
// an octile .map read into an OccupancyGrid (row 0 of the file is the top, row 0 of the grid the
// bottom; one cell per metre) and its .map.scen problems with cells already in grid rows.
#pragma once

#include <string>
#include <vector>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

struct MovingAiProblem {
  int bucket = 0;
  CellIndex start;
  CellIndex goal;
  double octileOptimum = 0.0;
};

// `.` and `G` are free, every other character occupied. Throws FileError / FormatError.
OccupancyGrid loadMovingAiMap(const std::string& path);
// The problems of a .map.scen for a map of `height` rows. Throws FileError / FormatError.
std::vector<MovingAiProblem> loadMovingAiScenario(const std::string& path, int height);

}  // namespace rgnav
