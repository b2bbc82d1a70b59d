// scoreObjects: the RG Map's 2D objects (each region's rectangles, RegionObjects.h) against the
// floor plan's furniture (FurnitureTruth.h: cells occupied in X_furnitures.png and free in X.png,
// 8-connected blobs). An object is on furniture if at least kMinFurnitureShare of its footprint
// (its outline placed into the floor plan with the region's frame and mapToWorld, rasterised as
// the object evaluation does, Detection.h) are furniture cells, so a room-sized rectangle with a
// cabinet in it is not; the blobs those cells belong to count as found. Specks (blobs below
// minBlobCells) count for neither. Rectangles only find furniture whose sides the laser sees as
// lines (cabinets, shelves, desks with side panels), not table or chair legs, so the found share
// is low by design; the share of objects on furniture says whether what the kernel calls an
// object is one.
#pragma once

#include <cstddef>

#include "core/common/Pose2D.h"
#include "core/objects/ConvexPolygon.h"
#include "core/raster/OccupancyGrid.h"
#include "tests/eval/objects/FurnitureTruth.h"
#include "tests/eval/rooms/FinalMap.h"

namespace rgnav {

inline constexpr double kMinFurnitureShare = 0.5;

struct ObjectScore {
  std::size_t objects = 0, onFurniture = 0;  // RG Map objects, those on a furniture blob
  std::size_t blobs = 0, blobsFound = 0;     // furniture blobs (no specks), those an object lies on
};

// The corners of object `o` of `region` in the floor plan's frame, counter-clockwise.
Polygon objectOutlineInWorld(const RegionView& region, const RectangleObjectView& o, const Pose2D& mapToWorld);

ObjectScore scoreObjects(const FinalMap& map, const Pose2D& mapToWorld, const OccupancyGrid& world,
                         const FurnitureTruth& furniture);

}  // namespace rgnav
