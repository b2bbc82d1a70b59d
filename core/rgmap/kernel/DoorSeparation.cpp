// Whether a door separates its two sides (see DoorSeparation.h).
#include "core/rgmap/kernel/DoorSeparation.h"

#include <array>
#include <cmath>
#include <deque>
#include <string>
#include <utility>
#include <vector>

#include "core/common/Errors.h"
#include "core/rgmap/describe/RegionFreespace.h"
#include "core/rgmap/kernel/GatewayGeometry.h"

namespace rgnav {
namespace {

// The local occupancy grid around `centre`: every scan taken within `reach` of it (in both axes),
// its beams cut at the square of half-width `reach`.
RegionFreespace localGrid(const RgMapState& state, const Eigen::Vector2d& centre, double reach, double cellSizeM) {
  const Eigen::Vector2d c00 = centre - Eigen::Vector2d(reach, reach), c11 = centre + Eigen::Vector2d(reach, reach);
  const Eigen::Vector2d c10(c11.x(), c00.y()), c01(c00.x(), c11.y());
  const std::array<GatewaySegment, 4> border{{{c00, c10}, {c10, c11}, {c11, c01}, {c01, c00}}};
  FreespaceConfig grid;
  grid.cellSizeM = cellSizeM;
  RegionFreespace freespace(grid);
  for (const auto& [id, stored] : state.scans) {
    const Eigen::Vector2d at(stored.corrected.x, stored.corrected.y);
    if ((at - centre).cwiseAbs().maxCoeff() < reach) freespace.addScan(stored.scan, stored.corrected, border);
  }
  return freespace;
}

// A door's slab: its line lengthened and thickened (map frame).
struct Slab {
  Eigen::Vector2d mid, along, normal;
  double halfLength = 0.0, halfDepth = 0.0;

  Slab(const Gateway& door, const DoorSeparationConfig& config) {
    const PlacedGateway placed = placeGateway(door);
    const Eigen::Vector2d a = placed.gatewayPoints[0], b = placed.gatewayPoints[1];
    mid = 0.5 * (a + b);
    along = (b - a).normalized();
    normal = {-along.y(), along.x()};
    // A cell is blocked where the slab touches it, give or take the cell's corners.
    halfLength = 0.5 * (b - a).norm() + config.overhangM + 0.5 * config.cellSizeM;
    halfDepth = config.slabHalfDepthM + 0.5 * config.cellSizeM;
  }
  bool contains(const Eigen::Vector2d& p) const {
    const Eigen::Vector2d d = p - mid;
    return std::abs(d.dot(along)) <= halfLength && std::abs(d.dot(normal)) <= halfDepth;
  }
};

// The cells within radiusM of a door's midpoint, in a square window: passable or not.
class LocalWay {
 public:
  LocalWay(const RegionFreespace& grid, const Eigen::Vector2d& mid, double radiusM)
      : grid_(grid), centre_(grid.cellOf(mid)), half_(static_cast<int>(std::ceil(radiusM / grid.cellSizeM()))),
        open_(std::size_t(2 * half_ + 1) * std::size_t(2 * half_ + 1), false) {
    for (int j = -half_; j <= half_; ++j)
      for (int i = -half_; i <= half_; ++i) {
        const int ci = centre_.i + i, cj = centre_.j + j;
        open_[index(i, j)] = (grid.cellCenter(ci, cj) - mid).norm() <= radiusM && passable(ci, cj);
      }
  }

  void block(const Slab& slab) {
    for (int j = -half_; j <= half_; ++j)
      for (int i = -half_; i <= half_; ++i)
        if (slab.contains(grid_.cellCenter(centre_.i + i, centre_.j + j))) open_[index(i, j)] = false;
  }

  // Whether a 4-connected path of open cells joins the cells that contain `from` and `to`.
  bool joins(const Eigen::Vector2d& from, const Eigen::Vector2d& to) const {
    const auto local = [&](const Eigen::Vector2d& p) {
      const LatticeCell c = grid_.cellOf(p);
      return std::pair{c.i - centre_.i, c.j - centre_.j};
    };
    const auto start = local(from), goal = local(to);
    if (!open(start.first, start.second) || !open(goal.first, goal.second)) return false;
    std::vector<bool> seen(open_.size(), false);
    std::deque<std::pair<int, int>> queue{start};
    seen[index(start.first, start.second)] = true;
    while (!queue.empty()) {
      const auto [i, j] = queue.front();
      queue.pop_front();
      if (std::pair{i, j} == goal) return true;
      for (const auto& [ni, nj] : std::array<std::pair<int, int>, 4>{{{i + 1, j}, {i - 1, j}, {i, j + 1}, {i, j - 1}}})
        if (open(ni, nj) && !seen[index(ni, nj)]) {
          seen[index(ni, nj)] = true;
          queue.emplace_back(ni, nj);
        }
    }
    return false;
  }

 private:
  std::size_t index(int i, int j) const { return std::size_t(j + half_) * std::size_t(2 * half_ + 1) + std::size_t(i + half_); }
  bool open(int i, int j) const { return std::abs(i) <= half_ && std::abs(j) <= half_ && open_[index(i, j)]; }
  bool passable(int i, int j) const {
    if (grid_.cell(i, j) != FreespaceCell::Free) return false;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di)
        if (grid_.cell(i + di, j + dj) == FreespaceCell::Occupied) return false;
    return true;
  }

  const RegionFreespace& grid_;
  LatticeCell centre_;
  int half_;
  std::vector<bool> open_;
};

}  // namespace

void validate(const DoorSeparationConfig& config) {
  const std::array<std::pair<double, const char*>, 6> sizes{{{config.cellSizeM, "cellSizeM"},
                                                             {config.radiusM, "radiusM"},
                                                             {config.scanMarginM, "scanMarginM"},
                                                             {config.slabHalfDepthM, "slabHalfDepthM"},
                                                             {config.overhangM, "overhangM"},
                                                             {config.seedOffsetM, "seedOffsetM"}}};
  for (const auto& [value, name] : sizes)
    if (!std::isfinite(value) || value <= 0.0)
      throw ConfigError(std::string("door separation: ") + name + " must be positive and finite");
}

bool separatesSpace(const RgMapState& state, GatewayId id, const DoorSeparationConfig& config) {
  const Slab door(state.gateways.at(id), config);
  const RegionFreespace grid = localGrid(state, door.mid, config.radiusM + config.scanMarginM, config.cellSizeM);
  LocalWay way(grid, door.mid, config.radiusM);
  way.block(door);
  for (const auto& [other, g] : state.gateways) {
    if (other == id || !g.door() || g.neutralised || g.sides[kSideA].region == 0 || g.sides[kSideB].region == 0)
      continue;
    const Slab slab(g, config);
    if ((slab.mid - door.mid).norm() <= config.radiusM + slab.halfLength + slab.halfDepth) way.block(slab);
  }
  const double seed = config.slabHalfDepthM + config.seedOffsetM;
  return !way.joins(door.mid + seed * door.normal, door.mid - seed * door.normal);
}

}  // namespace rgnav
