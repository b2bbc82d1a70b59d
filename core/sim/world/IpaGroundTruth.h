// loadIpaGroundTruth: ground truth of the IPA room segmentation benchmark maps (Bormann et al.,
// ICRA 2016) as floorplans/SOURCES.md derives it. Rooms: the 8-connected components of free
// pixels (gray >= 250) of X_gt_segmentation.png, components of <= 100 px dropped. Door lines:
// the pixels free in X.png but not in the GT image form one blob per drawn separator (blobs of
// < 5 px are drawing specks); each blob becomes a segment along its principal axis, from the
// smallest to the largest projection of its pixel centres, with the rooms on either side found
// by probing perpendicular to it.
//
// Not every blob is a doorway: where the GT image draws a wall thicker than X.png does (along
// corridors of lab_b_scan, at its left border), the blob runs along the wall and its line has
// the same room, or no room, on both sides; an L-shaped separator (lab_intel, top right) gives
// one diagonal line. The blob count still matches gt_stats.tsv.
#pragma once

#include <string>

#include "core/raster/OccupancyGrid.h"
#include "core/sim/GroundTruth.h"

namespace rgnav {

constexpr int kIpaMinRoomPixels = 101;
constexpr int kIpaMinSeparatorPixels = 5;
constexpr double kIpaDoorProbeDistance = 1.0;  // m, how far to look for the rooms beside a separator

// `geometry` is the world grid of the map (loadFloorPlan of X.png or X_furnitures.png); both
// images must have its size (InvalidArgumentError otherwise). File errors name the path.
GroundTruth loadIpaGroundTruth(const std::string& gtPngPath, const std::string& emptyPngPath,
                               const OccupancyGrid& geometry);

}  // namespace rgnav
