// Particles of removed regions moved into the refreshed map (see ParticleRehoming.h).
#include "servers/localization/ParticleRehoming.h"

#include <algorithm>
#include <map>

namespace rgnav {

std::vector<Particle> rehomedParticles(std::vector<Particle> particles, const std::vector<Orphan>& orphans,
                                       const LocalizationMap& map, const std::vector<RegionId>& fetched) {
  const auto moveInto = [&](std::size_t i, RegionId to, const Pose2D& pose) {
    particles[i] = {to, between(map.region(to).frame, pose), particles[i].weight};
  };
  std::map<RegionId, std::size_t> homes;
  std::vector<Orphan> homeless;
  for (const Orphan& o : orphans) {
    const RegionId to = map.regionAt({o.mapPose.x, o.mapPose.y}, RegionId());
    if (to.isNone()) {
      homeless.push_back(o);
    } else {
      moveInto(o.index, to, o.mapPose);
      ++homes[to];
    }
  }
  RegionId fallback;
  for (const auto& [id, count] : homes)
    if (fallback.isNone() || count > homes.at(fallback)) fallback = id;
  if (fallback.isNone()) {
    for (const RegionId id : fetched)
      if (map.hasRegion(id) && (fallback.isNone() || id < fallback)) fallback = id;
  }
  std::vector<bool> dropped(particles.size(), false);
  for (const Orphan& o : homeless) {
    dropped[o.index] = fallback.isNone();
    if (!fallback.isNone()) moveInto(o.index, fallback, o.mapPose);
  }
  std::vector<Particle> kept;
  for (std::size_t i = 0; i < particles.size(); ++i)
    if (!dropped[i]) kept.push_back(particles[i]);
  return kept;
}

}  // namespace rgnav
