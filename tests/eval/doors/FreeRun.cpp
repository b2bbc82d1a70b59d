// Free-space runs on a grid (see FreeRun.h).
#include "tests/eval/doors/FreeRun.h"

namespace rgnav {

double freeRunM(const OccupancyGrid& grid, const Eigen::Vector2d& from, const Eigen::Vector2d& direction, double maxM) {
  const double step = grid.resolution() / 2.0;
  double run = 0.0;
  for (double d = 0.0; d <= maxM; d += step) {
    const Eigen::Vector2d p = from + d * direction;
    const auto cell = grid.cellOf({p.x(), p.y()});
    if (!cell || grid.blocked(*cell)) break;
    run = d;
  }
  return run;
}

}  // namespace rgnav
