// writeExplorationImage: the picture of one exploration for a person to look at, one pixel per
// floor-plan pixel, north up: walls and furniture dark grey; the reachable free area
// (TruthCoverage.h) light green where the true laser saw it, red where it did not; free cells out
// of reach light grey; the ground-truth separators black; the final RG Map's regions
// (RegionPixels.h, not grown) as outlines in their map colours with their IDs; the true path blue,
// its start a black ring.
#pragma once

#include <Eigen/Core>
#include <span>
#include <string>

#include "tests/eval/exploration/TruthCoverage.h"
#include "tests/eval/rooms/FinalMap.h"

namespace rgnav {

// Throws FileError naming the path.
void writeExplorationImage(const std::string& path, const OccupancyGrid& world, const GroundTruth& truth,
                           const TruthCoverage& coverage, std::span<const Eigen::Vector2d> truePath,
                           const FinalMap& map, const Pose2D& mapToWorld);

}  // namespace rgnav
