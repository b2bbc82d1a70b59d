// The ground-truth door rule (see DoorTruth.h).
#include "tests/eval/doors/DoorTruth.h"

#include <algorithm>

#include "core/gateways/passages/SegmentCrossing.h"
#include "tests/eval/doors/FreeRun.h"

namespace rgnav {
namespace {

constexpr double kMaxSideRunM = 30.0;

// Width of the free space through `p` parallel to `along`, summed over both directions.
double widthThrough(const OccupancyGrid& grid, const Eigen::Vector2d& p, const Eigen::Vector2d& along) {
  return freeRunM(grid, p, along, kMaxSideRunM) + freeRunM(grid, p, -along, kMaxSideRunM);
}

}  // namespace

std::vector<TruthDoor> doorTruth(const GroundTruth& truth, const OccupancyGrid& emptyMap,
                                 const std::vector<int>& unreachableRooms, const std::vector<Eigen::Vector2d>& path,
                                 const DoorRule& rule) {
  const auto unreachable = [&](int room) {
    return std::find(unreachableRooms.begin(), unreachableRooms.end(), room) != unreachableRooms.end();
  };
  std::vector<TruthDoor> doors;
  for (const DoorLine& line : truth.doors) {
    TruthDoor door{line};
    const Eigen::Vector2d a(line.a.x, line.a.y), b(line.b.x, line.b.y);
    door.midpoint = 0.5 * (a + b);
    door.widthM = (b - a).norm();
    const Eigen::Vector2d along = door.widthM > 0.0 ? Eigen::Vector2d((b - a) / door.widthM) : Eigen::Vector2d(1, 0);
    const Eigen::Vector2d normal(-along.y(), along.x());
    for (int side = 0; side < 2; ++side) {
      const Eigen::Vector2d beside = door.midpoint + (side == 0 ? 1.0 : -1.0) * rule.sideOffsetM * normal;
      door.sideWidthM[side] = widthThrough(emptyMap, beside, along);
    }
    const bool narrower = door.widthM < rule.narrowerFactor * std::min(door.sideWidthM[0], door.sideWidthM[1]);
    if (line.roomA < 0 || line.roomB < 0 || line.roomA == line.roomB)
      door.exclusion = DoorExclusion::kNotBetweenRooms;
    else if (unreachable(line.roomA) || unreachable(line.roomB))
      door.exclusion = DoorExclusion::kUnreachable;
    else if (door.widthM > rule.maxDoorWidthM || !narrower)
      door.exclusion = DoorExclusion::kNotNarrow;
    else if (std::none_of(path.begin(), path.end(),
                          [&](const Eigen::Vector2d& p) { return (p - door.midpoint).norm() <= rule.approachM; }))
      door.exclusion = DoorExclusion::kNotApproached;
    for (std::size_t i = 1; i < path.size() && !door.traversed; ++i)
      door.traversed = segmentCrossing(path[i - 1], path[i], a, b).has_value();
    doors.push_back(door);
  }
  return doors;
}

std::string exclusionName(DoorExclusion exclusion) {
  switch (exclusion) {
    case DoorExclusion::kNone: return "door";
    case DoorExclusion::kNotBetweenRooms: return "not-between-rooms";
    case DoorExclusion::kUnreachable: return "unreachable";
    case DoorExclusion::kNotNarrow: return "not-narrow";
    case DoorExclusion::kNotApproached: return "not-approached";
  }
  return "?";
}

}  // namespace rgnav
