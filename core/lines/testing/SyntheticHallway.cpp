// Synthetic hallway and a drive along it; see SyntheticHallway.h.
#include "core/lines/testing/SyntheticHallway.h"

#include <cmath>

#include "core/common/Errors.h"

namespace rgnav::testing {
namespace {

constexpr double kHalfWidthM = 1.0;
constexpr double kDoorSpacingM = 5.0, kDoorWidthM = 0.9, kNicheDepthM = 0.3;
constexpr double kCabinetSpacingM = 7.0;

// One side wall (y = side * kHalfWidthM) with door niches centred at first, first + 2 * kDoorSpacingM, ...
void sideWall(std::vector<Wall>& walls, double lengthM, double side, double first) {
  const double y = side * kHalfWidthM, back = side * (kHalfWidthM + kNicheDepthM);
  double x = 0.0;
  for (double door = first; door + kDoorWidthM < lengthM; door += 2.0 * kDoorSpacingM) {
    const double x0 = door - kDoorWidthM / 2, x1 = door + kDoorWidthM / 2;
    walls.push_back({{x, y}, {x0, y}});
    walls.push_back({{x0, y}, {x0, back}});
    walls.push_back({{x0, back}, {x1, back}});
    walls.push_back({{x1, back}, {x1, y}});
    x = x1;
  }
  walls.push_back({{x, y}, {lengthM, y}});
}

}  // namespace

std::vector<Wall> hallwayWalls(double lengthM) {
  if (!(lengthM >= 4.0)) throw InvalidArgumentError("synthetic hallway: need a length of at least 4 m");
  std::vector<Wall> walls;
  sideWall(walls, lengthM, -1.0, kDoorSpacingM / 2);
  sideWall(walls, lengthM, 1.0, 1.5 * kDoorSpacingM);
  walls.push_back({{0.0, -kHalfWidthM}, {0.0, kHalfWidthM}});
  walls.push_back({{lengthM, -kHalfWidthM}, {lengthM, kHalfWidthM}});
  double side = 1.0;
  for (double x = kCabinetSpacingM / 2; x + 0.5 < lengthM; x += kCabinetSpacingM, side = -side) {
    const auto cabinet = boxWalls({x, side * (kHalfWidthM - 0.2)}, 0.0, 0.6, 0.4);
    walls.insert(walls.end(), cabinet.begin(), cabinet.end());
  }
  return walls;
}

std::vector<LaserScan> hallwayScans(double lengthM, std::size_t scans, const ScanSpec& spec) {
  if (scans < 2) throw InvalidArgumentError("synthetic hallway: need at least two scans");
  const std::vector<Wall> walls = hallwayWalls(lengthM);
  const double track = lengthM - 2.0;
  std::vector<LaserScan> out;
  out.reserve(scans);
  ScanSpec each = spec;
  for (std::size_t k = 0; k < scans; ++k) {
    // Distance driven along the out-and-back track, in [0, 2 * track].
    const double driven = 2.0 * track * double(k) / double(scans - 1);
    const bool back = driven > track;
    const double x = 1.0 + (back ? 2.0 * track - driven : driven);
    const double y = 0.2 * std::sin(x / 1.5);
    const double slope = std::atan(0.2 / 1.5 * std::cos(x / 1.5));
    const Pose2D pose{x, y, back ? normalizeAngle(M_PI + slope) : slope};
    each.seed = spec.seed + unsigned(k);
    out.push_back(syntheticScan(walls, pose, each));
  }
  return out;
}

}  // namespace rgnav::testing
