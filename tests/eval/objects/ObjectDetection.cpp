// The evaluation's object detection pipeline; see ObjectDetection.h.
#include "tests/eval/objects/ObjectDetection.h"

#include <algorithm>
#include <cmath>

#include "core/lines/RegionLineMap.h"
#include "core/objects/OverlapSuppression.h"
#include "core/objects/PointClustering.h"
#include "tests/eval/objects/FreeSpace.h"
#include "tests/eval/objects/PointCloud.h"
#include "tests/eval/objects/StructureLines.h"

namespace rgnav {
namespace {

constexpr int kCircleVertices = 32;
constexpr double kMaxDuplicateIoU = 0.5;  // rectangles of neighbouring rooms' maps

Polygon circleOutline(const Circle2D& c) {
  Polygon polygon;
  for (int k = 0; k < kCircleVertices; ++k) {
    const double a = 2.0 * M_PI * k / kCircleVertices;
    polygon.push_back(c.center + c.radiusM * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return polygon;
}

bool seenThrough(const Detection& d, const OccupancyGrid& geometry, const FreeSpace& free, double maxShare) {
  const std::vector<std::size_t> cells = footprint(d, geometry);
  const auto seen = std::count_if(cells.begin(), cells.end(), [&](std::size_t c) { return free.seenFree(c); });
  return static_cast<double>(seen) > maxShare * static_cast<double>(cells.size());
}

bool onAny(const std::vector<Detection>& kept, const Eigen::Vector2d& p, double margin) {
  return std::any_of(kept.begin(), kept.end(), [&](const Detection& d) { return insideConvex(d.outline, p, margin); });
}

// Diagonal of the axis-aligned bounding box.
double extent(const std::vector<Eigen::Vector2d>& points) {
  Eigen::Vector2d lo = points.front(), hi = lo;
  for (const auto& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).norm();
}

// Rectangles of every room's line map that the laser did not see through, duplicates removed.
std::vector<Detection> keptRectangles(const std::vector<Detection>& candidates, const OccupancyGrid& geometry,
                                      const FreeSpace& free, double maxShare) {
  std::vector<Detection> solid;
  std::vector<Polygon> outlines;
  std::vector<double> scores;
  for (const Detection& d : candidates)
    if (!seenThrough(d, geometry, free, maxShare)) {
      solid.push_back(d);
      outlines.push_back(d.outline);
      scores.push_back(d.score);
    }
  std::vector<Detection> kept;
  for (const std::size_t i : suppressOverlaps(outlines, scores, OverlapMeasure::kIntersectionOverUnion, kMaxDuplicateIoU))
    kept.push_back(solid[i]);
  return kept;
}

// Small isolated objects among the cloud points not explained by `kept` objects.
void addSmallObjects(const std::vector<CloudPoint>& points, const std::vector<bool>& onStructure,
                     const ObjectDetectionParams& params, std::vector<Detection>& kept) {
  std::vector<std::size_t> rest;
  std::vector<Eigen::Vector2d> surfaces;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!onAny(kept, points[i].surface, params.onObjectMarginM)) {
      rest.push_back(i);
      surfaces.push_back(points[i].surface);
    }
  std::vector<Detection> small;
  for (const auto& group : clusterPoints(surfaces, params.isolationGapM)) {
    if (std::any_of(group.begin(), group.end(), [&](std::size_t k) { return onStructure[rest[k]]; })) continue;
    std::vector<Eigen::Vector2d> pushed;
    for (const std::size_t k : group) pushed.push_back(points[rest[k]].pushed);
    for (const auto& object : clusterPoints(pushed, params.objectGapM)) {
      if (object.size() < params.minClusterPoints) continue;
      std::vector<Eigen::Vector2d> members;
      for (const std::size_t k : object) members.push_back(pushed[k]);
      if (extent(members) > params.maxClusterExtentM) continue;
      small.push_back({DetectionKind::kCluster, convexHull(members), members, static_cast<double>(members.size())});
    }
  }
  kept.insert(kept.end(), small.begin(), small.end());
}

}  // namespace

DetectionSummary detectObjects(const TourScans& tour, const OccupancyGrid& geometry,
                               const ObjectDetectionParams& params) {
  DetectionSummary out;
  const RectangleDetector rectangleDetector(params.rectangles);
  StructureLines structure(params.structureDistanceM);
  PointCloud cloud(geometry.resolution());
  FreeSpace free(geometry);
  std::vector<Detection> rectangleCandidates;
  for (const std::vector<LaserScan>& scans : tour.byRoom) {
    RegionLineMap map;
    for (std::size_t i = 0; i < scans.size(); ++i) {
      map.addScan(scans[i], scans[i].sensorPose);
      cloud.add(scans[i]);
      if (i % params.freeSpaceScanStride == 0) free.add(scans[i]);
    }
    out.scans += scans.size();
    out.mapLines += map.lines().size();
    for (const LineSegment& line : map.lines())
      if (line.length() >= params.structureLengthM) structure.add(line);
    for (const Rectangle2D& r : rectangleDetector.detect(map.lines()))
      rectangleCandidates.push_back(
          {DetectionKind::kRectangle, rectangleOutline(r), {Eigen::Vector2d(r.pose.x, r.pose.y)}, r.confidence});
  }
  const std::vector<CloudPoint>& points = cloud.points();
  out.cloudPoints = points.size();
  out.hitCells.assign(geometry.cells().size(), false);
  for (const CloudPoint& p : points)
    if (const auto c = geometry.cellOf({p.pushed.x(), p.pushed.y()}))
      out.hitCells[static_cast<std::size_t>(c->row) * geometry.width() + c->col] = true;

  std::vector<Detection> kept = keptRectangles(rectangleCandidates, geometry, free, params.maxSeenFreeShare);

  std::vector<bool> onStructure(points.size());
  std::vector<Eigen::Vector2d> objectPoints;
  for (std::size_t i = 0; i < points.size(); ++i) {
    onStructure[i] = structure.onLine(points[i].surface);
    if (!onStructure[i]) objectPoints.push_back(points[i].surface);
  }
  std::vector<Detection> circles;
  for (const Circle2D& c : CircleDetector(params.circles).detect(objectPoints)) {
    const Detection d{DetectionKind::kCircle, circleOutline(c), {c.center}, c.confidence};
    if (!seenThrough(d, geometry, free, params.maxSeenFreeShare) && !onAny(kept, c.center, params.onObjectMarginM))
      circles.push_back(d);
  }
  kept.insert(kept.end(), circles.begin(), circles.end());
  addSmallObjects(points, onStructure, params, kept);
  out.detections = std::move(kept);
  return out;
}

}  // namespace rgnav
