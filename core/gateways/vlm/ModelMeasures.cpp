// Distance and rectangularity measures; see ModelMeasures.h.
#include "core/gateways/vlm/ModelMeasures.h"

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

double distanceMeasure(const GatewayPoints& points, double hallwayWidthM) {
  if (!(hallwayWidthM > 0.0)) throw InvalidArgumentError("distance measure: the hallway width must be positive");
  double sum = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = (points[(i + 1) % points.size()] - points[i]).norm();
    sum += 1.0 - std::sqrt(std::fabs(d - hallwayWidthM) / hallwayWidthM);
  }
  return 0.25 * sum;
}

double rectangularityMeasure(const GatewayPoints& points) {
  double deviation = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d a = points[(i + points.size() - 1) % points.size()] - points[i];
    const Eigen::Vector2d b = points[(i + 1) % points.size()] - points[i];
    const double na = a.norm(), nb = b.norm();
    const double alpha = na > 0.0 && nb > 0.0 ? std::acos(std::clamp(a.dot(b) / (na * nb), -1.0, 1.0)) : 0.0;
    deviation += std::fabs(alpha - M_PI / 2);
  }
  return 1.0 - deviation / (2.0 * M_PI);
}

}  // namespace rgnav
