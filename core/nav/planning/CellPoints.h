// CellPoints: small helpers on points in cell units (SegmentVisibility.h) that the planners share:
// the free cell a point lies in, a point's name for messages, and a polyline's length.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

// A free cell the point lies in or on the border of, preferring the cell below-left of grid lines;
// none for a non-finite point or one in no free cell.
std::optional<CellIndex> freeCellAt(const OccupancyGrid& grid, const Eigen::Vector2d& p);

// "(x, y)".
std::string pointName(const Eigen::Vector2d& p);

double polylineLength(const std::vector<Eigen::Vector2d>& points);

}  // namespace rgnav
