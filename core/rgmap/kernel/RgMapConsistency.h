// checkConsistency: the global consistency check of an RG Map (thesis 6.1.1: "Performing a global
// check for consistency on the Region & Gateway Graph"; 2.1: each region refers to its adjacent
// gateways and each gateway knows the regions it links). It lists every violated invariant:
//   - references both ways: a region lists exactly the gateways that name it on a side, and every
//     region a gateway names exists;
//   - each gateway joins at most two regions through two distinct, known crossing points (a
//     narrow passage through crossing points 0 and 1), and detector IDs are not shared;
//   - a gateway is flagged neutralised iff it has the same region on both sides;
//   - no region is empty, except the current one (the robot may have just entered it);
//   - every stored scan lies in exactly one region, every region's scans are stored, ascending;
//   - IDs below the next IDs, the current region exists, names are unique, event IDs consecutive.
// The kernel's tests run it after every step; a resumed checkpoint must pass it (RgMapCodec.h).
// Deliberate difference: the thesis only suggests such a check to find ambiguous gateways
// (figure 6.6); we check the map's structure, and leave the repair to the kernel's rules.
#pragma once

#include <string>
#include <vector>

#include "core/rgmap/kernel/RgMapState.h"

namespace rgnav {

// One message per violation, naming the region, gateway or scan; empty when consistent.
std::vector<std::string> checkConsistency(const RgMapState& state);

}  // namespace rgnav
