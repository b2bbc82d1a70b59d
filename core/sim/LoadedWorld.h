// loadWorld: a simulator world from any of the files the simulator accepts, with its ground
// truth where the world has one:
//   - an occupancy image (PNG/PGM floor plan, 0.05 m/px, gray >= 250 free); an IPA floor plan
//     X.png or X_furnitures.png gets its rooms and doors from X_gt_segmentation.png beside it;
//   - a ROS map_server YAML (has an `image` key), with a navigation task if it has `start` and
//     `goal` keys (NavigationTask.h: the BARN worlds);
//   - a vector world YAML (walls, doors, furniture, 3D rectangles, rooms).
#pragma once

#include <optional>
#include <string>

#include "core/raster/OccupancyGrid.h"
#include "core/sim/GroundTruth.h"
#include "core/sim/world/NavigationTask.h"

namespace rgnav {

struct LoadedWorld {
  OccupancyGrid grid;
  std::optional<GroundTruth> truth;
  std::optional<NavigationTask> task;
};

// The files an IPA-format floor plan comes with (same folder, named after the base map X).
struct IpaFiles {
  std::string name;   // the given file's stem, e.g. lab_a_scan_furnitures
  std::string empty;  // X.png
  std::string truth;  // X_gt_segmentation.png
};
IpaFiles ipaFilesOf(const std::string& floorPlanPath);

// Throws FileError / FormatError / ConfigError naming the file.
LoadedWorld loadWorld(const std::string& path);

}  // namespace rgnav
