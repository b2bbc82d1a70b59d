// GroundTruthTour: the simulator's room tour, a TourPlanner route (core/nav/grid) through the
// rooms of a world's ground truth, checked to share the grid's geometry.
#pragma once

#include "core/common/Pose2D.h"
#include "core/nav/grid/TourPlanner.h"
#include "core/sim/GroundTruth.h"

namespace rgnav {

// Throws InvalidArgumentError if the ground truth does not share the grid's size, resolution and
// origin; otherwise as planTour over the ground truth's room labels.
Tour planTour(const OccupancyGrid& grid, const GroundTruth& truth, const Pose2D& start,
              const GridPlannerConfig& config = {});

}  // namespace rgnav
