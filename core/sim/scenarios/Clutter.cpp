// Clutter: the two clutter levels' densities and sizes, and rejection sampling of placements.
#include "core/sim/scenarios/Clutter.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rgnav {

namespace {

struct Range {
  double lo;
  double hi;
};

struct LevelSpec {
  double wallObjectsPerMetre;     // objects per metre of wall face
  double middlePeoplePerSquareMetre;
  Range potDiameter;              // m
  Range boxSide;                  // m
};

constexpr Range kPersonDiameter{0.35, 0.45};  // people seen by a laser at 0.4 m height
constexpr double kWallGap = 0.1;              // m, largest gap between an object and its wall
constexpr double kObjectGap = 0.1;            // m between objects
constexpr int kDrawsPerObject = 30;

LevelSpec specOf(ClutterLevel level) {
  if (level == ClutterLevel::Strong) {
    return {1.0 / 3.0, 1.0 / 10.0, {0.4, 0.7}, {0.4, 0.9}};
  }
  return {1.0 / 8.0, 0.0, {0.3, 0.45}, {0.3, 0.5}};
}

double uniform(std::mt19937_64& rng, Range r) { return std::uniform_real_distribution<double>(r.lo, r.hi)(rng); }

double length(const WallFace& w) { return std::hypot(w.b.x - w.a.x, w.b.y - w.a.y); }

ClutterObject wallObject(const WallFace& wall, const LevelSpec& spec, std::mt19937_64& rng) {
  ClutterObject o;
  o.kind = static_cast<ClutterKind>(std::uniform_int_distribution<int>(0, 2)(rng));
  double depth = 0.0;  // extent from the wall into the hallway
  if (o.kind == ClutterKind::Box) {
    const double along = uniform(rng, spec.boxSide);
    depth = uniform(rng, spec.boxSide);
    const bool alongX = std::abs(wall.inward.y) > 0.5;  // the wall runs along x
    o.halfX = (alongX ? along : depth) / 2.0;
    o.halfY = (alongX ? depth : along) / 2.0;
  } else {
    depth = uniform(rng, o.kind == ClutterKind::Person ? kPersonDiameter : spec.potDiameter);
    o.halfX = o.halfY = depth / 2.0;
  }
  const double t = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
  const double off = std::uniform_real_distribution<double>(0.0, kWallGap)(rng) + depth / 2.0;
  o.centre = {wall.a.x + t * (wall.b.x - wall.a.x) + off * wall.inward.x,
              wall.a.y + t * (wall.b.y - wall.a.y) + off * wall.inward.y};
  return o;
}

ClutterObject middlePerson(const WorldRect& hallway, std::mt19937_64& rng) {
  ClutterObject o;
  o.kind = ClutterKind::Person;
  o.halfX = o.halfY = uniform(rng, kPersonDiameter) / 2.0;
  o.centre = {uniform(rng, {hallway.minX + o.halfX, hallway.maxX - o.halfX}),
              uniform(rng, {hallway.minY + o.halfY, hallway.maxY - o.halfY})};
  return o;
}

bool overlaps(const ClutterObject& o, const WorldRect& r, double gap) {
  return o.centre.x + o.halfX + gap > r.minX && o.centre.x - o.halfX - gap < r.maxX &&
         o.centre.y + o.halfY + gap > r.minY && o.centre.y - o.halfY - gap < r.maxY;
}

bool acceptable(const ClutterObject& o, const HallwayLayout& layout, const WorldRect& keepClear,
                const std::vector<ClutterObject>& placed) {
  if (!insideHallways(layout, o.centre) || overlaps(o, keepClear, 0.0)) {
    return false;
  }
  return std::none_of(placed.begin(), placed.end(), [&o](const ClutterObject& p) {
    return overlaps(o, {p.centre.x - p.halfX, p.centre.y - p.halfY, p.centre.x + p.halfX, p.centre.y + p.halfY},
                    kObjectGap);
  });
}

// Draws up to kDrawsPerObject candidates from `draw` and keeps the first acceptable one.
template <typename Draw>
void place(Draw draw, const HallwayLayout& layout, const WorldRect& keepClear,
           std::vector<ClutterObject>& placed) {
  for (int attempt = 0; attempt < kDrawsPerObject; ++attempt) {
    const ClutterObject o = draw();
    if (acceptable(o, layout, keepClear, placed)) {
      placed.push_back(o);
      return;
    }
  }
}

// Index drawn with probability proportional to weights.
std::size_t weightedIndex(const std::vector<double>& weights, std::mt19937_64& rng) {
  return std::discrete_distribution<std::size_t>(weights.begin(), weights.end())(rng);
}

}  // namespace

std::string_view clutterLevelName(ClutterLevel level) {
  switch (level) {
    case ClutterLevel::None: return "uncluttered";
    case ClutterLevel::Slight: return "slightly cluttered";
    case ClutterLevel::Strong: return "strongly cluttered";
  }
  return "unknown";
}

std::vector<ClutterObject> placeClutter(const HallwayLayout& layout, ClutterLevel level,
                                        const WorldRect& keepClear, std::mt19937_64& rng) {
  std::vector<ClutterObject> placed;
  if (level == ClutterLevel::None) {
    return placed;
  }
  const LevelSpec spec = specOf(level);
  std::vector<double> wallLengths;
  for (const WallFace& w : layout.walls) {
    wallLengths.push_back(length(w));
  }
  const double totalWall = std::accumulate(wallLengths.begin(), wallLengths.end(), 0.0);
  const auto wallCount = static_cast<int>(std::lround(totalWall * spec.wallObjectsPerMetre));
  for (int i = 0; i < wallCount; ++i) {
    place([&] { return wallObject(layout.walls[weightedIndex(wallLengths, rng)], spec, rng); },
          layout, keepClear, placed);
  }
  std::vector<double> areas;
  for (const WorldRect& r : layout.hallways) {
    areas.push_back((r.maxX - r.minX) * (r.maxY - r.minY));
  }
  const double totalArea = std::accumulate(areas.begin(), areas.end(), 0.0);
  const auto middleCount = static_cast<int>(std::lround(totalArea * spec.middlePeoplePerSquareMetre));
  for (int i = 0; i < middleCount; ++i) {
    place([&] { return middlePerson(layout.hallways[weightedIndex(areas, rng)], rng); }, layout,
          keepClear, placed);
  }
  return placed;
}

void drawClutter(OccupancyGrid& grid, const std::vector<ClutterObject>& objects) {
  for (const ClutterObject& o : objects) {
    if (o.kind == ClutterKind::Box) {
      fillRect(grid, {o.centre.x - o.halfX, o.centre.y - o.halfY, o.centre.x + o.halfX, o.centre.y + o.halfY},
               Cell::Occupied);
    } else {
      fillDisk(grid, o.centre, o.halfX, Cell::Occupied);
    }
  }
}

}  // namespace rgnav
