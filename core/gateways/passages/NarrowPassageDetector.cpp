// Narrow passages in one scan per viewing direction (see NarrowPassageDetector.h).
#include "core/gateways/passages/NarrowPassageDetector.h"

#include <algorithm>
#include <optional>
#include <tuple>
#include <utility>

#include "core/gateways/passages/GatewayPointWalk.h"
#include "core/gateways/passages/JambSurfaces.h"
#include "core/gateways/passages/OpenSpaceBehind.h"
#include "core/gateways/passages/ScanBeams.h"
#include "core/lines/ScanPoints.h"

namespace rgnav {
namespace {

// The scan's points in the sensor frame, their bearings and surfaces.
struct LocalScan {
  const LaserScan& scan;
  std::vector<ScanPoint> points;
  std::vector<double> bearings;
  JambSurfaces surfaces;

  LocalScan(const LaserScan& s, const BreakpointParams& breaks)
      : scan(s), points(scanPoints(s, Pose2D{})), surfaces(points, s.angleIncrement, breaks) {
    for (const ScanPoint& p : points) bearings.push_back(bearingOf(s, p.beam));
  }
};

// Index of the closest point with a bearing in the open interval (lo, hi), as the thesis'
// ranges α_m - Δα < α < α_m and α_m < α < α_m + Δα.
std::optional<std::size_t> closestIn(const LocalScan& local, double lo, double hi) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < local.points.size(); ++i)
    if (lo < local.bearings[i] && local.bearings[i] < hi &&
        (!best || local.points[i].rangeM < local.points[*best].rangeM))
      best = i;
  return best;
}

// A checked pair of gateway-point candidates (indices into LocalScan::points).
struct Pair {
  std::size_t right = 0, left = 0;
  double widthM = 0.0, distanceM = 0.0, apertureRad = 0.0, confidence = 0.0;
};

class DirectionSearch {
 public:
  DirectionSearch(const NarrowPassageConfig& config, const LocalScan& local)
      : config_(config), local_(local), minWidthM_(minPassageWidthM(config)) {}

  // The minimum-width valid pair for viewing direction alphaM, if any. The candidates are the
  // closest points P_right, P_left, the ends of the walks from each towards the other, and
  // (ours) the point of each walk nearest to the other side's walk end: where a door meets a
  // side wall, the walk turns the corner and runs along that wall, and its end lies deeper in
  // the room than the corner that bounds the opening.
  std::optional<Pair> search(double alphaM) const {
    const auto right = closestIn(local_, alphaM - config_.halfRangeRad, alphaM);
    const auto left = closestIn(local_, alphaM, alphaM + config_.halfRangeRad);
    if (!right || !left) return std::nullopt;
    const auto rightEdge = walkToOpening(local_.scan, local_.points, *right, *left, minWidthM_);
    const auto leftEdge = walkToOpening(local_.scan, local_.points, *left, *right, minWidthM_);
    if (!rightEdge || !leftEdge) return std::nullopt;
    const std::size_t rightNearest = nearestTo(*right, *rightEdge, *leftEdge);
    const std::size_t leftNearest = nearestTo(*leftEdge, *left, rightNearest);
    std::optional<Pair> best;
    for (const std::size_t r : {*right, *rightEdge, rightNearest})
      for (const std::size_t l : {*left, *leftEdge, leftNearest})
        if (const auto pair = check(alphaM, r, l); pair && (!best || pair->widthM < best->widthM)) best = pair;
    return best;
  }

 private:
  // The point with index in [first, last] nearest to point `target`.
  std::size_t nearestTo(std::size_t first, std::size_t last, std::size_t target) const {
    std::size_t best = first;
    for (std::size_t i = first; i <= last; ++i)
      if ((local_.points[i].position - local_.points[target].position).norm() <
          (local_.points[best].position - local_.points[target].position).norm())
        best = i;
    return best;
  }

  std::optional<Pair> check(double alphaM, std::size_t r, std::size_t l) const {
    const ScanPoint& pr = local_.points[r];
    const ScanPoint& pl = local_.points[l];
    Pair pair{r, l, (pl.position - pr.position).norm()};
    if (pair.widthM <= minWidthM_ || pair.widthM >= config_.maxDoorWidthM) return std::nullopt;
    // The line of sight must cross the segment between the points, at P_is.
    if (!(local_.bearings[r] < alphaM && alphaM < local_.bearings[l])) return std::nullopt;
    const Eigen::Vector2d sight(std::cos(alphaM), std::sin(alphaM));
    const Eigen::Vector2d e = pl.position - pr.position;
    const double cross = sight.x() * e.y() - sight.y() * e.x();
    if (cross == 0.0) return std::nullopt;
    pair.distanceM = (pr.position.x() * e.y() - pr.position.y() * e.x()) / cross;
    if (pair.distanceM >= config_.maxDistanceM) return std::nullopt;
    pair.apertureRad = local_.bearings[l] - local_.bearings[r];
    if (pair.apertureRad < config_.minApertureRad) return std::nullopt;
    if (!gatewayPoints(r, l)) return std::nullopt;
    const SeeThrough behind =
        seeThrough(local_.scan, pr, pl, local_.points[local_.surfaces.surfaceEnd(r, -1)].beam,
                   local_.points[local_.surfaces.surfaceEnd(l, +1)].beam, config_.minDepthBehindM);
    if (behind.beyond < config_.minBeamsBehind) return std::nullopt;
    pair.confidence = double(behind.beyond) / double(behind.beams);
    return pair;
  }

  // Both candidates are jambs, and one of them is a wall end in line with the passage (a door in
  // a wall, a door at a room corner, a gap between a partition's end and the wall opposite). This
  // rejects lines across hallways (both points in the middle of walls, or one at a door jamb in
  // the hallway's side wall, across it) and gaps between table legs.
  bool gatewayPoints(std::size_t r, std::size_t l) const {
    if (!jamb(r, -1) || !jamb(l, +1)) return false;
    const bool rightEnd = local_.surfaces.surfaceEnd(r, -1) == r, leftEnd = local_.surfaces.surfaceEnd(l, +1) == l;
    return (rightEnd && inLine(r, -1, l)) || (leftEnd && inLine(l, +1, r));
  }

  // Not hidden behind a nearer object, and bounding a surface of at least minJambLengthM away
  // from the passage.
  bool jamb(std::size_t candidate, int away) const {
    return !local_.surfaces.hiddenBehindNeighbour(candidate, away) &&
           local_.surfaces.jambLengthM(candidate, away) >= config_.minJambLengthM;
  }

  // The candidate's surface continues the gateway line outwards for minWallEndLengthM (within
  // wallEndToleranceM).
  bool inLine(std::size_t candidate, int away, std::size_t other) const {
    return local_.surfaces.continuesLine(candidate, away, local_.points[candidate].position,
                                         local_.points[other].position, config_.minWallEndLengthM,
                                         config_.wallEndToleranceM);
  }

  const NarrowPassageConfig& config_;
  const LocalScan& local_;
  double minWidthM_;
};

}  // namespace

NarrowPassageDetector::NarrowPassageDetector(const NarrowPassageConfig& config) : config_(config) {
  validate(config_);
}

std::vector<PassageHypothesis> NarrowPassageDetector::detect(const LaserScan& scan, const Pose2D& sensorPose) const {
  if (scan.ranges.empty() || scan.angleIncrement <= 0.0) return {};
  const LocalScan local(scan, config_.surfaceBreaks);
  const DirectionSearch directions(config_, local);
  const double first = bearingOf(scan, 0), last = bearingOf(scan, scan.ranges.size() - 1);
  // Viewing directions 0, ±step, ±2 step, ... strictly inside the field of view.
  std::vector<std::pair<Pair, double>> found;  // with its viewing direction
  const int steps = static_cast<int>(std::ceil(std::max(-first, last) / config_.viewingStepRad));
  for (int k = -steps; k <= steps; ++k) {
    const double alphaM = k * config_.viewingStepRad;
    if (alphaM <= first || alphaM >= last) continue;
    if (const auto pair = directions.search(alphaM)) found.emplace_back(*pair, alphaM);
  }
  // The minimum-width pair across directions: narrowest first, and a pair whose points enclose
  // or straddle those of a narrower one is the same opening seen wider.
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
    return std::tie(a.first.widthM, a.first.distanceM) < std::tie(b.first.widthM, b.first.distanceM);
  });
  std::vector<PassageHypothesis> hypotheses;
  std::vector<std::pair<std::size_t, std::size_t>> taken;
  for (const auto& candidate : found) {
    const Pair& pair = candidate.first;  // not a structured binding: clang 14 cannot capture one
    const double alphaM = candidate.second;
    const bool overlaps = std::any_of(taken.begin(), taken.end(), [&](const auto& t) {
      return pair.right < t.second && t.first < pair.left;
    });
    if (overlaps) continue;
    taken.emplace_back(pair.right, pair.left);
    hypotheses.push_back({scan.id, transformPoint(sensorPose, local.points[pair.left].position),
                          transformPoint(sensorPose, local.points[pair.right].position), pair.widthM, pair.distanceM,
                          pair.apertureRad, alphaM, pair.confidence});
  }
  std::sort(hypotheses.begin(), hypotheses.end(),
            [](const PassageHypothesis& a, const PassageHypothesis& b) { return a.distanceM < b.distanceM; });
  return hypotheses;
}

}  // namespace rgnav
