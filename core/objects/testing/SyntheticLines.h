// Test and benchmark helper: reproducible synthetic 2D line maps with rectangular objects among
// clutter, for comparing grouping searches.
#pragma once

#include <vector>

#include "core/lines/LineSegment.h"

namespace rgnav::testing {

// `count` segments with IDs 1..count in a 20 x 20 m area: about 40 % are the sides of boxes
// (sides 0.4-2 m, turned at random, each side shortened at its ends by up to 8 cm so corners are
// open but closer than 200 mm, directions disturbed by up to 1.5 degrees), the rest clutter
// segments of 0.2-3 m at any place and orientation. Shuffled; the same for the same seed.
std::vector<LineSegment> syntheticLineMap(std::size_t count, unsigned seed);

}  // namespace rgnav::testing
