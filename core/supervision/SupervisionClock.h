// The clock that supervision decisions are expressed in. The supervision logic never reads it;
// callers pass `now` in, so the logic is deterministic under test.
#pragma once

#include <chrono>

namespace rgnav {

using SupervisionClock = std::chrono::steady_clock;

}  // namespace rgnav
