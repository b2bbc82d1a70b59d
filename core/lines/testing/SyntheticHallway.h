// Test helper: a long straight hallway with door niches and cabinets, and the scans of a robot
// driving along it to the far end and back, for region line maps that keep growing (thesis 5.2:
// a hallway region can hold thousands of scans).
#pragma once

#include <cstddef>
#include <vector>

#include "core/lines/testing/SyntheticScan.h"

namespace rgnav::testing {

// The walls of a hallway from x = 0 to x = lengthM, 2 m wide (|y| <= 1), closed at both ends,
// with a 0.9 m door niche (0.3 m deep) every 5 m on alternating sides and a 0.6 x 0.4 m cabinet
// against a wall every 7 m. Throws InvalidArgumentError for lengthM < 4.
std::vector<Wall> hallwayWalls(double lengthM);

// `scans` scans as given by `spec` (seed spec.seed + k for scan k) from sensor poses evenly
// spaced along the hallway, from x = 1 to lengthM - 1 and back, weaving 0.2 m sideways. Throws
// InvalidArgumentError for lengthM < 4 or scans < 2.
std::vector<LaserScan> hallwayScans(double lengthM, std::size_t scans, const ScanSpec& spec = {});

}  // namespace rgnav::testing
