// The room evaluation's --list output; see Listing.h.
#include "tests/eval/rooms/Listing.h"

#include <Eigen/Geometry>
#include <cstdio>
#include <map>

#include "core/gateways/detection/GatewayRecord.h"
#include "core/lines/ScanPoints.h"

namespace rgnav {
namespace {

using ULL = unsigned long long;

double share(std::size_t a, std::size_t b) { return b == 0 ? 0.0 : double(a) / double(b); }

// The centre of each ground-truth room, world frame.
std::vector<Eigen::Vector2d> roomCentres(const GroundTruth& truth) {
  std::vector<Eigen::Vector2d> sum(std::size_t(truth.roomCount), Eigen::Vector2d::Zero());
  std::vector<double> count(sum.size(), 0.0);
  const auto width = std::size_t(truth.width);
  for (std::size_t i = 0; i < truth.labels.size(); ++i)
    if (const int room = truth.labels[i]; room >= 0) {
      sum[std::size_t(room)] += Eigen::Vector2d(double(i % width), double(i / width));
      ++count[std::size_t(room)];
    }
  for (std::size_t r = 0; r < sum.size(); ++r)
    sum[r] = Eigen::Vector2d(truth.origin.x, truth.origin.y) +
             truth.resolution * (sum[r] / count[r] + Eigen::Vector2d(0.5, 0.5));
  return sum;
}

// Whether `p` (world) lies beyond a door of `region`: see Listing.h.
bool beyondOwnDoor(const MappingRun& run, RegionId region, const Eigen::Vector2d& p) {
  for (const GatewayView& g : run.map.gateways) {
    if (!g.door || g.neutralised || g.crossingPoints.size() != 2) continue;
    for (const std::size_t side : {0u, 1u}) {
      const RegionId own = side == 0 ? g.sideA : g.sideB;
      if (own != region) continue;
      const Eigen::Vector2d mine = transformPoint(run.mapToWorld, g.crossingPoints[side]);
      const Eigen::Vector2d other = transformPoint(run.mapToWorld, g.crossingPoints[1 - side]);
      if ((p - 0.5 * (mine + other)).norm() < kBeyondRadiusM && (p - other).norm() < (p - mine).norm()) return true;
    }
  }
  return false;
}

void printRooms(const RoomScore& score, const GroundTruth& truth) {
  const std::vector<Eigen::Vector2d> centres = roomCentres(truth);
  for (const RoomMatch& r : score.rooms) {
    const Eigen::Vector2d& c = centres[std::size_t(r.room)];
    std::printf("#   room %2d at (%6.2f, %6.2f): %7zu px, recall %.3f", r.room, c.x(), c.y(), r.pixels, r.recall());
    if (r.segment != kNoMatch) std::printf(" (region %llu)", ULL(score.segments[r.segment].id));
    std::printf("\n");
  }
}

void printRegions(const RoomScore& score, const GroundTruth& truth, const MappingRun& run) {
  for (const SegmentMatch& s : score.segments) {
    const std::vector<DataId>& scans = run.regionScans.at(RegionId(s.id));
    Eigen::AlignedBox2d box;
    std::map<int, std::size_t> byRoom;
    std::size_t beyond = 0;
    for (const DataId id : scans) {
      const Eigen::Vector2d& p = run.truePath[id - 1];
      box.extend(p);
      ++byRoom[truth.roomAt({p.x(), p.y()})];
      beyond += beyondOwnDoor(run, RegionId(s.id), p);
    }
    std::printf("#   region %3llu: %5zu scans (%llu..%llu) in (%.1f, %.1f)-(%.1f, %.1f), %zu beyond own doors, by room:",
                ULL(s.id), scans.size(), ULL(scans.front()), ULL(scans.back()), box.min().x(), box.min().y(),
                box.max().x(), box.max().y(), beyond);
    for (const auto& [room, n] : byRoom) std::printf(" %d (%zu)", room, n);
    std::printf("\n#     %7zu px, precision %.3f (room %d); rooms >= 5 %%:", s.pixels, s.precision(), s.room);
    for (std::size_t r = 0; r < s.roomOverlaps.size(); ++r)
      if (double(s.roomOverlaps[r]) >= 0.05 * double(s.pixels))
        std::printf(" %zu (%.2f)", r, share(s.roomOverlaps[r], s.pixels));
    std::printf("\n");
  }
}

void printGateways(const MappingRun& run) {
  for (const GatewayView& g : run.map.gateways) {
    const Eigen::Vector2d a = transformPoint(run.mapToWorld, g.gatewayPoints.front());
    const Eigen::Vector2d b = transformPoint(run.mapToWorld, g.gatewayPoints[g.gatewayPoints.size() / 2]);
    std::printf("#   gateway %3llu (%s) (%6.2f, %6.2f)-(%6.2f, %6.2f): regions %llu|%llu, traversals %zu%s\n", ULL(g.id.value()),
                g.classes.front().name == kNarrowPassageClass ? "door" : g.classes.front().name.c_str(), a.x(), a.y(),
                b.x(), b.y(), ULL(g.sideA.value()),
                ULL(g.sideB.value()), g.traversals, g.neutralised ? ", neutralised" : "");
  }
}

}  // namespace

void printListing(const RoomScore& score, const GroundTruth& truth, const MappingRun& run) {
  printRooms(score, truth);
  printRegions(score, truth, run);
  printGateways(run);
}

}  // namespace rgnav
