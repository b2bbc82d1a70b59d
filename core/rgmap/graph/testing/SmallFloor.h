// Test helper: the RG graph description of a small hand-made floor. A hallway (region 1, y in
// [0, 2], x in [0, 20]) with an office (2) and a lab (3) above it and a lobby (4) at its east end:
//   gateway 10  hallway - office   opening at (3, 2)
//   gateway 11  hallway - lab      opening at (9, 2)
//   gateway 12  office  - lab      the one door, at (6, 5)
//   gateway 13  hallway - lobby    opening at (20, 1)
//   gateway 14  lobby   - lobby    neutralised (a false detection in the lobby) at (25, 4)
// Crossing points lie 0.5 m on either side of each gateway, so every gateway edge is 1 m long.
#pragma once

#include "core/rgmap/graph/RgGraph.h"

namespace rgnav::testing {

inline constexpr RegionId kHallway{1}, kOffice{2}, kLab{3}, kLobby{4};
inline constexpr GatewayId kHallOffice{10}, kHallLab{11}, kOfficeLabDoor{12}, kHallLobby{13}, kLobbyFalse{14};

RgGraphSpec smallFloor();

}  // namespace rgnav::testing
