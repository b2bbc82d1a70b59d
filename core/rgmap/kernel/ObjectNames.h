// Names of 2D objects (issue semantics: "names for regions and objects, lookup by name"). A
// region's objects are derived from its line map (RegionObjects.h) and detected anew whenever the
// region changes, so a name cannot be tied to an index: the kernel keeps each name with the
// centre of the object it was given to, in the map frame (Region::objectNames), and a name
// belongs to the object of the region's current description whose outline, grown by
// kObjectNameReachM, holds that position (the nearest centre if several do).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/objects/RectangleDetector.h"
#include "core/rgmap/kernel/RgMapState.h"

namespace rgnav {

// How far an object may move from where it was named (re-detection after new scans, pose
// corrections) and keep its name.
inline constexpr double kObjectNameReachM = 0.3;

// The index of the object a name given at `point` belongs to; nullopt if none holds it.
std::optional<std::size_t> objectAt(const std::vector<Rectangle2D>& objects, const Eigen::Vector2d& point);

// The index of the object of `region` (`objects`: its description's, region frame) that a name
// kept at `namedAt` (map frame, Region::objectNames) belongs to; nullopt if none holds it.
std::optional<std::size_t> objectNamedAt(const Region& region, const std::vector<Rectangle2D>& objects,
                                         const Eigen::Vector2d& namedAt);

// The name of each of `objects` (the objects of `region`'s description, region frame); empty for
// an unnamed one. Of two names for one object the first in name order counts.
std::vector<std::string> objectNamesOf(const Region& region, const std::vector<Rectangle2D>& objects);

// Moves to `to` every name of `from` whose object is no longer among `fromObjects` but is among
// `toObjects` (each region's description's objects, in its own frame): the part split off a
// region takes the names of the objects it took.
void moveObjectNames(Region& from, const std::vector<Rectangle2D>& fromObjects, Region& to,
                     const std::vector<Rectangle2D>& toObjects);

}  // namespace rgnav
