// FreespaceSeeding: the particles of a global localization without any clue where the robot is:
// spread uniformly over the free cells of every region's freespace bitmap (thesis 5.2: 15 cm
// cells), each at a uniform position inside its cell and a uniform heading, in its region's
// frame. Where regions' freespace overlaps (around gateways) the overlap gets the particles of
// both. This is the Localization module's relocalize() until the region-recognition seeder
// (core/nav/localization GlobalLocalizer, issue 28) replaces it at that one call site.
#pragma once

#include <cstddef>
#include <random>
#include <vector>

#include "core/nav/localization/LocalizationMap.h"
#include "core/nav/localization/Particle.h"

namespace rgnav {

// `count` particles of equal weight; NotAvailableError if no region has a free cell.
std::vector<Particle> uniformFreespaceParticles(const LocalizationMap& map, std::size_t count, std::mt19937_64& rng);

}  // namespace rgnav
