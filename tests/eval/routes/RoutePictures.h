// RoutePictures: the pictures of the routes evaluation, to look at what the figures say:
//   - the RG map (RgMapPng.h) with the pairs whose RG path is longest against the whole-floor path,
//     the RG path in red and the whole-floor path in blue, start and goal as green dots;
//   - one region's planning grid (RegionGrid.h) with its framed quadtree (quads outlined, frame
//     cells shaded) and a smoothed region path, the picture of thesis figure 5.6 e.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/nav/planning/RoutePlanner.h"
#include "core/rgmap/export/RgMapSnapshot.h"

namespace rgnav {

struct ComparedPaths {
  std::vector<Eigen::Vector2d> rg, floor;  // map frame
};

// Throws FileError naming the path when it cannot be written.
void writeRoutesPicture(const std::string& path, const RgMapSnapshot& map, const std::vector<ComparedPaths>& pairs);

// The region's grid at `config`'s resolution and radius, its quadtree and the region path from
// `from` (map frame, free in the region) to the farthest free cell it reaches. Throws NoPathError
// when it reaches none, FileError when the file cannot be written.
void writeQuadtreePicture(const std::string& path, const RegionView& region, const RoutePlannerConfig& config,
                          const Eigen::Vector2d& from);

}  // namespace rgnav
