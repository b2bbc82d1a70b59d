// Greedy nearest-midpoint matching of gateways to GT doors (see DoorMatching.h).
#include "tests/eval/doors/DoorMatching.h"

#include <algorithm>
#include <tuple>

namespace rgnav {
namespace {

enum class Role { kCounted, kIgnored, kFalse, kNone };

Role roleOf(const TruthDoor& door, bool traversedOnly) {
  switch (door.exclusion) {
    case DoorExclusion::kNone: return traversedOnly && !door.traversed ? Role::kIgnored : Role::kCounted;
    case DoorExclusion::kUnreachable:
    case DoorExclusion::kNotApproached: return Role::kIgnored;
    case DoorExclusion::kNotNarrow: return Role::kFalse;
    case DoorExclusion::kNotBetweenRooms: return Role::kNone;
  }
  return Role::kNone;
}

}  // namespace

DoorMatch matchDoors(const std::vector<TruthDoor>& doors, const std::vector<Eigen::Vector2d>& detectionMidpoints,
                     double maxDistanceM, bool traversedOnly) {
  DoorMatch m;
  m.outcomes.assign(detectionMidpoints.size(), DetectionOutcome::kFalse);
  m.detectionOfDoor.assign(doors.size(), -1);
  // Counted doors first, then the other lines; nearest first within each.
  std::vector<std::tuple<bool, double, std::size_t, std::size_t>> pairs;  // not counted, distance, door, detection
  for (std::size_t d = 0; d < doors.size(); ++d) {
    const Role role = roleOf(doors[d], traversedOnly);
    m.doors += role == Role::kCounted;
    if (role == Role::kNone) continue;
    for (std::size_t k = 0; k < detectionMidpoints.size(); ++k)
      if (const double dist = (doors[d].midpoint - detectionMidpoints[k]).norm(); dist <= maxDistanceM)
        pairs.emplace_back(role != Role::kCounted, dist, d, k);
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> taken(detectionMidpoints.size(), false);
  for (const auto& [notCounted, dist, d, k] : pairs) {
    if (taken[k] || m.detectionOfDoor[d] >= 0) continue;
    taken[k] = true;
    m.detectionOfDoor[d] = static_cast<int>(k);
    const Role role = roleOf(doors[d], traversedOnly);
    if (role == Role::kCounted) m.outcomes[k] = DetectionOutcome::kMatch;
    if (role == Role::kIgnored) m.outcomes[k] = DetectionOutcome::kIgnored;
  }
  for (const DetectionOutcome o : m.outcomes) {
    m.detections += o != DetectionOutcome::kIgnored;
    m.matches += o == DetectionOutcome::kMatch;
  }
  return m;
}

}  // namespace rgnav
