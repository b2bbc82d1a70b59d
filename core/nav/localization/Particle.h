// Particle: one hypothesis of the region Monte Carlo localization: the region it is in, its pose
// in that region's frame (thesis 5.3: each particle is evaluated on its own region's data) and
// its weight.
#pragma once

#include "core/common/Pose2D.h"
#include "core/rgmap/graph/RgGraphKeys.h"

namespace rgnav {

struct Particle {
  RegionId region;
  Pose2D pose;          // in the region's frame
  double weight = 0.0;  // normalised over the set after each update

  friend bool operator==(const Particle&, const Particle&) = default;
};

}  // namespace rgnav
