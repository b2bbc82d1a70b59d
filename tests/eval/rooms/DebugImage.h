// Pictures of one evaluated map for a person to look at, one pixel per floor-plan pixel, north up:
// walls and furniture dark grey; region pixels (RegionPixels.h) in their RG Map colours
// (MapColours.h), darkened where two or more of the drawn regions claim a pixel; ground-truth room
// pixels none of the drawn regions covers red; ground-truth separator lines black; the RG Map's
// gateways in their export colours (doors orange, hallway areas blue, neutralised grey), its 2D
// objects as purple outlines; each
// drawn region's ID at the centre of its pixels.
//   - writeRoomImage: every region;
//   - writeRegionImage: one region, with the true robot positions of its scans as black dots
//     (which scans a region holds is what explains most of its pixels).
#pragma once

#include <Eigen/Core>
#include <span>
#include <string>

#include "core/common/Pose2D.h"
#include "core/raster/OccupancyGrid.h"
#include "core/sim/GroundTruth.h"
#include "tests/eval/rooms/FinalMap.h"
#include "tests/eval/rooms/RoomScoring.h"

namespace rgnav {

// Throw FileError naming the path.
void writeRoomImage(const std::string& path, const OccupancyGrid& world, const GroundTruth& truth,
                    const FinalMap& map, const Pose2D& mapToWorld, std::span<const SegmentPixels> regions);
void writeRegionImage(const std::string& path, const OccupancyGrid& world, const GroundTruth& truth,
                      const FinalMap& map, const Pose2D& mapToWorld, const SegmentPixels& region,
                      std::span<const Eigen::Vector2d> scanPositions);

}  // namespace rgnav
