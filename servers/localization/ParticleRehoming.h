// ParticleRehoming: what becomes of the particles of regions the kernel merged away (or split),
// so that a map refresh does not throw the filter back to a global localization. A particle of a
// removed region keeps its map pose (taken before the region's frame went) and moves into the
// region whose freespace holds that pose now - the merged region, as a rule. One whose pose no
// region's freespace holds (the 15 cm bitmap misses cells next to walls) goes where most of the
// others went, or else into the lowest ID among the regions fetched anew (a merge keeps the lower
// ID, and the merged region changed); with none of these it is dropped.
#pragma once

#include <cstddef>
#include <vector>

#include "core/nav/localization/LocalizationMap.h"
#include "core/nav/localization/Particle.h"

namespace rgnav {

struct Orphan {
  std::size_t index = 0;  // into the particle set
  Pose2D mapPose;         // before its region went
};

// The particle set with the orphans moved (and the dropped ones left out), in the original order;
// `map` is the refreshed map, `fetched` the regions fetched anew by the refresh.
std::vector<Particle> rehomedParticles(std::vector<Particle> particles, const std::vector<Orphan>& orphans,
                                       const LocalizationMap& map, const std::vector<RegionId>& fetched);

}  // namespace rgnav
