// Whether a door separates its two sides (see DoorSeparation.h).
#include "core/rgmap/kernel/DoorSeparation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
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

// A hallway area's square (any convex quadrangle of its gateway points, map frame), grown by
// overhangM and half a cell: in a real junction its corners are the walls' corners.
struct Square {
  std::vector<Eigen::Vector2d> corners;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double margin = 0.0;

  Square(const Gateway& area, const DoorSeparationConfig& config)
      : corners(placeGateway(area).gatewayPoints), margin(config.overhangM + 0.5 * config.cellSizeM) {
    for (const Eigen::Vector2d& c : corners) centre += c / double(corners.size());
  }
  double reach() const {
    double r = 0.0;
    for (const Eigen::Vector2d& c : corners) r = std::max(r, (c - centre).norm());
    return r;
  }
  bool contains(const Eigen::Vector2d& p) const {
    bool inside = true;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const Eigen::Vector2d a = corners[k], b = corners[(k + 1) % corners.size()];
      const Eigen::Vector2d ab = b - a;
      const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-12), 0.0, 1.0);
      nearest = std::min(nearest, (a + t * ab - p).norm());
      // Same side of every edge as the centre: inside the convex quadrangle.
      const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); };
      if (cross(ab, p - a) * cross(ab, centre - a) < 0.0) inside = false;
    }
    return inside || nearest <= margin;
  }
};

// The cells within radiusM of a door's midpoint, in a square window: passable or not.
class LocalWay {
 public:
  LocalWay(RegionFreespace grid, const Eigen::Vector2d& mid, double radiusM)
      : grid_(std::move(grid)), centre_(grid_.cellOf(mid)),
        half_(static_cast<int>(std::ceil(radiusM / grid_.cellSizeM()))),
        open_(2 * half_ + 1, 2 * half_ + 1, CV_8UC1, cv::Scalar(kClosed)) {
    for (int j = -half_; j <= half_; ++j)
      for (int i = -half_; i <= half_; ++i) {
        const int ci = centre_.i + i, cj = centre_.j + j;
        if ((grid_.cellCenter(ci, cj) - mid).norm() <= radiusM && passable(ci, cj)) at(i, j) = kOpen;
      }
  }

  // Closes every cell whose centre `shape` (a Slab or a Square) contains.
  template <typename Shape>
  void block(const Shape& shape) {
    for (int j = -half_; j <= half_; ++j)
      for (int i = -half_; i <= half_; ++i)
        if (shape.contains(grid_.cellCenter(centre_.i + i, centre_.j + j))) at(i, j) = kClosed;
  }

  // Whether a 4-connected path of open cells joins the cells that contain `from` and `to`: a
  // flood fill (cv::floodFill) from one reaches the other.
  bool joins(const Eigen::Vector2d& from, const Eigen::Vector2d& to) const {
    const auto local = [&](const Eigen::Vector2d& p) {
      const LatticeCell c = grid_.cellOf(p);
      return cv::Point(c.i - centre_.i + half_, c.j - centre_.j + half_);
    };
    const cv::Point start = local(from), goal = local(to);
    if (!open(start) || !open(goal)) return false;
    cv::Mat reached = open_.clone();
    cv::floodFill(reached, start, cv::Scalar(kReached), nullptr, cv::Scalar(), cv::Scalar(), 4);
    return reached.at<std::uint8_t>(goal) == kReached;
  }

 private:
  static constexpr std::uint8_t kClosed = 0, kOpen = 1, kReached = 2;

  // Window cell (i, j), both in [-half_, half_].
  std::uint8_t& at(int i, int j) { return open_.at<std::uint8_t>(j + half_, i + half_); }
  bool open(const cv::Point& p) const {
    return p.inside(cv::Rect(0, 0, open_.cols, open_.rows)) && open_.at<std::uint8_t>(p) == kOpen;
  }
  bool passable(int i, int j) const {
    if (grid_.cell(i, j) != FreespaceCell::Free) return false;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di)
        if (grid_.cell(i + di, j + dj) == FreespaceCell::Occupied) return false;
    return true;
  }

  RegionFreespace grid_;
  LatticeCell centre_;
  int half_;
  cv::Mat open_;  // CV_8UC1, kOpen or kClosed; row j + half_, column i + half_
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

namespace {

// The local way around `centre` within `radius`, with `id` and the doors between two regions
// nearby blocked.
template <typename Shape>
LocalWay wayAround(const RgMapState& state, GatewayId id, const Shape& shape, const Eigen::Vector2d& centre,
                   double radius, const DoorSeparationConfig& config) {
  LocalWay way(localGrid(state, centre, radius + config.scanMarginM, config.cellSizeM), centre, radius);
  way.block(shape);
  for (const auto& [other, g] : state.gateways) {
    if (other == id || !g.door() || g.neutralised || g.sides[kSideA].region == RegionId{} || g.sides[kSideB].region == RegionId{})
      continue;
    const Slab slab(g, config);
    if ((slab.mid - centre).norm() <= radius + slab.halfLength + slab.halfDepth) way.block(slab);
  }
  return way;
}

}  // namespace

bool separatesSpace(const RgMapState& state, GatewayId id, const DoorSeparationConfig& config) {
  const Slab door(state.gateways.at(id), config);
  const LocalWay way = wayAround(state, id, door, door.mid, config.radiusM, config);
  const double seed = config.slabHalfDepthM + config.seedOffsetM;
  return !way.joins(door.mid + seed * door.normal, door.mid - seed * door.normal);
}

bool areaSeparatesSides(const RgMapState& state, GatewayId id, std::size_t fromCrossing, std::size_t toCrossing,
                        const DoorSeparationConfig& config) {
  const Gateway& area = state.gateways.at(id);
  const Square square(area, config);
  const LocalWay way = wayAround(state, id, square, square.centre, square.reach() + config.radiusM, config);
  const PlacedGateway placed = placeGateway(area);
  const auto seed = [&](std::size_t crossing) {
    const Eigen::Vector2d c = placed.crossingPoints.at(crossing);
    return Eigen::Vector2d(c + (square.margin + config.seedOffsetM + config.cellSizeM) * (c - square.centre).normalized());
  };
  return !way.joins(seed(fromCrossing), seed(toCrossing));
}

}  // namespace rgnav
