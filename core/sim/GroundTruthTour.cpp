// GroundTruthTour: the geometry check before the tour over the ground truth's rooms.
#include "core/sim/GroundTruthTour.h"

#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

Tour planTour(const OccupancyGrid& grid, const GroundTruth& truth, const Pose2D& start,
              const GridPlannerConfig& config) {
  const bool same = truth.width == grid.width() && truth.height == grid.height() &&
                    std::abs(truth.resolution - grid.resolution()) < 1e-9 &&
                    std::abs(truth.origin.x - grid.origin().x) < 1e-9 &&
                    std::abs(truth.origin.y - grid.origin().y) < 1e-9;
  if (!same) {
    throw InvalidArgumentError("planTour: the ground truth does not have the grid's size, resolution and origin");
  }
  return planTour(grid, truth.labels, truth.roomCount, start, config);
}

}  // namespace rgnav
