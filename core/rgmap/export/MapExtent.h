// The part of the map frame an RG Map covers, for the pictures (RgMapSvg.h, RgMapPng.h) and the
// size comparison with an occupancy grid (MapStorage.h): the union of every region's freespace
// bitmap rectangle and line map and every gateway's gateway and crossing points, in the map frame.
#pragma once

#include <Eigen/Geometry>

#include "core/rgmap/export/RgMapSnapshot.h"

namespace rgnav {

// Empty (isEmpty()) for a map without any of the above.
Eigen::AlignedBox2d mapExtent(const RgMapSnapshot& map);

// The extent of the pictures: mapExtent grown by kPictureMarginM on every side; for an empty
// map, the square of that margin around the origin.
inline constexpr double kPictureMarginM = 0.5;
Eigen::AlignedBox2d pictureExtent(const RgMapSnapshot& map);

}  // namespace rgnav
