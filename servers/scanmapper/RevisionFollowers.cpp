// Followers of the pose revisions and what they have applied; see RevisionFollowers.h.
#include "servers/scanmapper/RevisionFollowers.h"

#include <algorithm>

namespace rgnav {

RevisionFollowers::RevisionFollowers(std::set<std::string> known) : known_(std::move(known)) {}

void RevisionFollowers::asked(const std::string& follower, std::uint64_t applied, double now) {
  std::erase_if(cursors_, [now](const auto& entry) { return now - entry.second.lastAsked >= kIdleSeconds; });
  if (!known_.contains(follower)) return;
  cursors_[follower] = Cursor{applied, now};
}

std::optional<std::uint64_t> RevisionFollowers::appliedByAll(double now) const {
  std::optional<std::uint64_t> lowest;
  for (const auto& [name, cursor] : cursors_)
    if (now - cursor.lastAsked < kIdleSeconds) lowest = std::min(lowest.value_or(cursor.applied), cursor.applied);
  return lowest;
}

}  // namespace rgnav
