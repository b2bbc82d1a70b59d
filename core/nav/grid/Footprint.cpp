// Footprint: exact overlap tests of a disk or a rotated rectangle against disks (closest point of
// the shape to the disk's centre) and against grid cells (the disk: DiskFootprint; the rectangle:
// the separating axis theorem for two convex polygons, as for oriented boxes in Gottschalk, Lin,
// Manocha, "OBBTree", SIGGRAPH 1996: the cell square's two axes and the rectangle's two). Thesis
// 5.5 checks the robot's swept outline against obstacles; this is the outline at one pose.
#include "core/nav/grid/Footprint.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/common/Errors.h"
#include "core/common/ValueChecks.h"
#include "core/nav/grid/DiskFootprint.h"

namespace rgnav {

namespace {

// The rectangle at a pose: its centre and its unit axes along (u) and across (n) the heading.
struct PlacedRectangle {
  WorldPoint centre;
  WorldPoint u;
  WorldPoint n;
  double halfLength;
  double halfWidth;
};

PlacedRectangle place(const Footprint& f, const Pose2D& pose) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  return {{pose.x + f.centerOffset * c, pose.y + f.centerOffset * s}, {c, s}, {-s, c}, f.length / 2.0, f.width / 2.0};
}

double dot(WorldPoint a, WorldPoint b) { return a.x * b.x + a.y * b.y; }

// Whether the open intervals [lo1, hi1] and [lo2, hi2] share more than a point.
bool intervalsOverlap(double lo1, double hi1, double lo2, double hi2) { return std::max(lo1, lo2) < std::min(hi1, hi2); }

// Whether the rectangle's interior meets the interior of the axis-aligned box [x0, x1] x [y0, y1].
bool overlapsBox(const PlacedRectangle& r, double x0, double x1, double y0, double y1) {
  // The rectangle's extent along world x and y.
  const double ex = r.halfLength * std::abs(r.u.x) + r.halfWidth * std::abs(r.n.x);
  const double ey = r.halfLength * std::abs(r.u.y) + r.halfWidth * std::abs(r.n.y);
  if (!intervalsOverlap(r.centre.x - ex, r.centre.x + ex, x0, x1)) return false;
  if (!intervalsOverlap(r.centre.y - ey, r.centre.y + ey, y0, y1)) return false;
  // The box's extent along the rectangle's axes.
  const WorldPoint boxCentre{(x0 + x1) / 2.0, (y0 + y1) / 2.0};
  const double hx = (x1 - x0) / 2.0, hy = (y1 - y0) / 2.0;
  const WorldPoint d{boxCentre.x - r.centre.x, boxCentre.y - r.centre.y};
  const double alongU = dot(d, r.u), alongN = dot(d, r.n);
  const double bu = hx * std::abs(r.u.x) + hy * std::abs(r.u.y);
  const double bn = hx * std::abs(r.n.x) + hy * std::abs(r.n.y);
  return intervalsOverlap(-r.halfLength, r.halfLength, alongU - bu, alongU + bu) &&
         intervalsOverlap(-r.halfWidth, r.halfWidth, alongN - bn, alongN + bn);
}

}  // namespace

Footprint Footprint::disk(double radius) {
  Footprint f;
  f.shape = Shape::Disk;
  f.radius = radius;
  return f;
}

Footprint Footprint::rectangle(double length, double width, double centerOffset) {
  Footprint f;
  f.shape = Shape::Rectangle;
  f.radius = 0.0;
  f.length = length;
  f.width = width;
  f.centerOffset = centerOffset;
  return f;
}

double Footprint::circumradius() const {
  if (shape == Shape::Disk) return radius;
  return std::hypot(std::abs(centerOffset) + length / 2.0, width / 2.0);
}

double Footprint::inscribedRadius() const {
  if (shape == Shape::Disk) return radius;
  return std::max(0.0, std::min(length / 2.0 - std::abs(centerOffset), width / 2.0));
}

std::vector<WorldPoint> Footprint::corners(const Pose2D& pose) const {
  if (shape == Shape::Disk) return {};
  const PlacedRectangle r = place(*this, pose);
  std::vector<WorldPoint> out;
  // Counter-clockwise from front right: (+l, -w), (+l, +w), (-l, +w), (-l, -w).
  for (const auto& [a, b] : std::array<std::pair<double, double>, 4>{{{1, -1}, {1, 1}, {-1, 1}, {-1, -1}}}) {
    out.push_back({r.centre.x + a * r.halfLength * r.u.x + b * r.halfWidth * r.n.x,
                   r.centre.y + a * r.halfLength * r.u.y + b * r.halfWidth * r.n.y});
  }
  return out;
}

bool Footprint::overlapsDisk(const Pose2D& pose, WorldPoint centre, double r) const {
  if (shape == Shape::Disk) return std::hypot(centre.x - pose.x, centre.y - pose.y) < radius + r;
  const PlacedRectangle rect = place(*this, pose);
  const WorldPoint d{centre.x - rect.centre.x, centre.y - rect.centre.y};
  // The disk centre in the rectangle's frame, and its distance to the rectangle (0 inside).
  const double u = std::abs(dot(d, rect.u)), n = std::abs(dot(d, rect.n));
  if (u < rect.halfLength && n < rect.halfWidth) return true;
  const double du = std::max(u - rect.halfLength, 0.0);
  const double dn = std::max(n - rect.halfWidth, 0.0);
  return du * du + dn * dn < r * r;
}

WorldPoint Footprint::nearestPoint(const Pose2D& pose, WorldPoint p) const {
  if (shape == Shape::Disk) {
    const double d = std::hypot(p.x - pose.x, p.y - pose.y);
    if (d <= radius) return p;
    return {pose.x + (p.x - pose.x) * radius / d, pose.y + (p.y - pose.y) * radius / d};
  }
  const PlacedRectangle rect = place(*this, pose);
  const WorldPoint d{p.x - rect.centre.x, p.y - rect.centre.y};
  const double u = std::clamp(dot(d, rect.u), -rect.halfLength, rect.halfLength);
  const double n = std::clamp(dot(d, rect.n), -rect.halfWidth, rect.halfWidth);
  return {rect.centre.x + u * rect.u.x + n * rect.n.x, rect.centre.y + u * rect.u.y + n * rect.n.y};
}

bool Footprint::overlapsGrid(const OccupancyGrid& grid, const Pose2D& pose) const {
  if (shape == Shape::Disk) return diskCollides(grid, {pose.x, pose.y}, radius);
  const PlacedRectangle r = place(*this, pose);
  const double ex = r.halfLength * std::abs(r.u.x) + r.halfWidth * std::abs(r.n.x);
  const double ey = r.halfLength * std::abs(r.u.y) + r.halfWidth * std::abs(r.n.y);
  const double res = grid.resolution();
  const WorldPoint o = grid.origin();
  const int col0 = static_cast<int>(std::floor((r.centre.x - ex - o.x) / res));
  const int col1 = static_cast<int>(std::floor((r.centre.x + ex - o.x) / res));
  const int row0 = static_cast<int>(std::floor((r.centre.y - ey - o.y) / res));
  const int row1 = static_cast<int>(std::floor((r.centre.y + ey - o.y) / res));
  for (int row = row0; row <= row1; ++row) {
    for (int col = col0; col <= col1; ++col) {
      if (!grid.blocked({col, row})) continue;
      if (overlapsBox(r, o.x + col * res, o.x + (col + 1) * res, o.y + row * res, o.y + (row + 1) * res)) return true;
    }
  }
  return false;
}

void validate(const Footprint& footprint) {
  if (footprint.shape == Footprint::Shape::Disk) {
    requirePositive(footprint.radius, "footprint radius");
    return;
  }
  requirePositive(footprint.length, "footprint length");
  requirePositive(footprint.width, "footprint width");
  if (!std::isfinite(footprint.centerOffset)) throw ConfigError("footprint centre offset must be finite");
}

}  // namespace rgnav
