// CellPoints: the planners' shared point helpers (see the header).
#include "core/nav/planning/CellPoints.h"

#include <cmath>
#include <sstream>

namespace rgnav {

std::optional<CellIndex> freeCellAt(const OccupancyGrid& grid, const Eigen::Vector2d& p) {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return std::nullopt;
  const double fx = std::floor(p.x()), fy = std::floor(p.y());
  if (fx < -1.0 || fy < -1.0 || fx > grid.width() || fy > grid.height()) return std::nullopt;
  const int col = static_cast<int>(fx), row = static_cast<int>(fy);
  for (int dc = 0; dc >= (fx == p.x() ? -1 : 0); --dc)
    for (int dr = 0; dr >= (fy == p.y() ? -1 : 0); --dr)
      if (!grid.blocked({col + dc, row + dr})) return CellIndex{col + dc, row + dr};
  return std::nullopt;
}

std::string pointName(const Eigen::Vector2d& p) {
  std::ostringstream out;
  out << "(" << p.x() << ", " << p.y() << ")";
  return out.str();
}

double polylineLength(const std::vector<Eigen::Vector2d>& points) {
  double length = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) length += (points[i] - points[i - 1]).norm();
  return length;
}

}  // namespace rgnav
