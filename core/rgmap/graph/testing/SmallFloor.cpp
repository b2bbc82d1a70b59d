// Test helper: a small hand-made floor as an RG graph description; see SmallFloor.h.
#include "core/rgmap/graph/testing/SmallFloor.h"

namespace rgnav::testing {

RgGraphSpec smallFloor() {
  return {{kHallway, kOffice, kLab, kLobby},
          {{kHallOffice, false, {kHallway, {3.0, 1.5}}, {kOffice, {3.0, 2.5}}},
           {kHallLab, false, {kHallway, {9.0, 1.5}}, {kLab, {9.0, 2.5}}},
           {kOfficeLabDoor, true, {kOffice, {5.5, 5.0}}, {kLab, {6.5, 5.0}}},
           {kHallLobby, false, {kHallway, {19.5, 1.0}}, {kLobby, {20.5, 1.0}}},
           {kLobbyFalse, false, {kLobby, {24.5, 4.0}}, {kLobby, {25.5, 4.0}}}}};
}

}  // namespace rgnav::testing
