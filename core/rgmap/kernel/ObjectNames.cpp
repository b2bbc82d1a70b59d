// The object a name belongs to; see ObjectNames.h.
#include "core/rgmap/kernel/ObjectNames.h"

#include "core/objects/ConvexPolygon.h"

namespace rgnav {

std::optional<std::size_t> objectAt(const std::vector<Rectangle2D>& objects, const Eigen::Vector2d& point) {
  std::optional<std::size_t> best;
  double bestDistance = 0.0;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (!insideConvex(rectangleOutline(objects[i]), point, kObjectNameReachM)) continue;
    const double d = (Eigen::Vector2d(objects[i].pose.x, objects[i].pose.y) - point).norm();
    if (!best || d < bestDistance) best = i, bestDistance = d;
  }
  return best;
}

std::optional<std::size_t> objectNamedAt(const Region& region, const std::vector<Rectangle2D>& objects,
                                         const Eigen::Vector2d& namedAt) {
  const Pose2D inRegion = between(region.frame, {namedAt.x(), namedAt.y(), 0.0});
  return objectAt(objects, {inRegion.x, inRegion.y});
}

std::vector<std::string> objectNamesOf(const Region& region, const std::vector<Rectangle2D>& objects) {
  std::vector<std::string> names(objects.size());
  for (const auto& [name, namedAt] : region.objectNames) {
    const std::optional<std::size_t> index = objectNamedAt(region, objects, namedAt);
    if (index && names[*index].empty()) names[*index] = name;
  }
  return names;
}

void moveObjectNames(Region& from, const std::vector<Rectangle2D>& fromObjects, Region& to,
                     const std::vector<Rectangle2D>& toObjects) {
  std::erase_if(from.objectNames, [&](const auto& entry) {
    const auto& [name, namedAt] = entry;
    if (objectNamedAt(from, fromObjects, namedAt) || !objectNamedAt(to, toObjects, namedAt)) return false;
    to.objectNames[name] = namedAt;
    return true;
  });
}

}  // namespace rgnav
