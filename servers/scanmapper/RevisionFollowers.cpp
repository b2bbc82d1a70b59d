// Followers of the pose revisions and what they have applied; see RevisionFollowers.h.
#include "servers/scanmapper/RevisionFollowers.h"

#include <algorithm>

namespace rgnav {

void RevisionFollowers::asked(const std::string& follower, std::uint64_t applied, double now) {
  if (follower.empty()) return;
  cursors_[follower] = Cursor{applied, now};
}

std::optional<std::uint64_t> RevisionFollowers::appliedByAll(double now) const {
  std::optional<std::uint64_t> lowest;
  for (const auto& [name, cursor] : cursors_)
    if (now - cursor.lastAsked < kIdleSeconds) lowest = std::min(lowest.value_or(cursor.applied), cursor.applied);
  return lowest;
}

}  // namespace rgnav
