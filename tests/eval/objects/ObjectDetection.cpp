// The evaluation's object detection pipeline; see ObjectDetection.h.
#include "tests/eval/objects/ObjectDetection.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/lines/PointMoments.h"
#include "core/lines/RegionLineMap.h"
#include "core/objects/OverlapSuppression.h"
#include "core/objects/PointClustering.h"
#include "tests/eval/objects/BeamEvidence.h"
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

Detection shapeDetection(DetectionKind kind, Polygon outline, const Eigen::Vector2d& centre, double score,
                         const OccupancyGrid& geometry) {
  std::vector<std::size_t> cells = rasterize(outline, {centre}, geometry);
  return {kind, std::move(outline), std::move(cells), score};
}

bool seenThrough(const Detection& d, const BeamEvidence& beams, double maxShare) {
  const auto seen = std::count_if(d.cells.begin(), d.cells.end(), [&](std::size_t c) { return beams.seenFree(c); });
  return static_cast<double>(seen) > maxShare * static_cast<double>(d.cells.size());
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

// True if the sensor moved or turned enough since `last` for the scan to add to a line map.
bool isKeyScan(const LaserScan& scan, const LaserScan* last, const ObjectDetectionParams& params) {
  if (last == nullptr) return true;
  const Pose2D d = between(last->sensorPose, scan.sensorPose);
  return std::hypot(d.x, d.y) >= params.keyScanDistanceM || std::fabs(d.theta) >= params.keyScanAngleRad;
}

// Rectangles of every room's line map that the laser did not see through, duplicates removed.
std::vector<Detection> keptRectangles(const std::vector<Detection>& candidates, const BeamEvidence& beams,
                                      double maxShare) {
  std::vector<Detection> solid;
  std::vector<Polygon> outlines;
  std::vector<double> scores;
  for (const Detection& d : candidates)
    if (!seenThrough(d, beams, maxShare)) {
      solid.push_back(d);
      outlines.push_back(d.outline);
      scores.push_back(d.score);
    }
  std::vector<Detection> kept;
  for (const std::size_t i :
       suppressOverlaps(outlines, scores, OverlapMeasure::kIntersectionOverUnion, kMaxDuplicateIoU))
    kept.push_back(solid[i]);
  return kept;
}

// Circles among the object points (clustered as the CircleDetector clusters them, so that each
// circle's points are known) that the laser did not see through, that are round (a straight line
// through their points fits clearly worse: a wall end seen head-on is flat) and that do not lie
// on a kept rectangle.
std::vector<Detection> keptCircles(const std::vector<Eigen::Vector2d>& objectPoints, const std::vector<Detection>& kept,
                                   const BeamEvidence& beams, const OccupancyGrid& geometry,
                                   const ObjectDetectionParams& params) {
  const CircleDetector detector(params.circles);
  std::vector<Detection> circles;
  std::vector<Eigen::Vector2d> cluster;
  for (const auto& members : clusterPoints(objectPoints, params.circles.clusterGapM)) {
    if (members.size() < params.circles.minPoints) continue;
    cluster.clear();
    PointMoments moments;
    for (const std::size_t i : members) {
      cluster.push_back(objectPoints[i]);
      moments.add(objectPoints[i]);
    }
    for (const Circle2D& c : detector.detect(cluster)) {
      if (moments.fitLine().rmsResidualM < params.minLineToCircleResidual * c.rmsResidualM) continue;
      Detection d = shapeDetection(DetectionKind::kCircle, circleOutline(c), c.center, c.confidence, geometry);
      if (!seenThrough(d, beams, params.maxSeenFreeShare) && !onAny(kept, c.center, params.onObjectMarginM))
        circles.push_back(std::move(d));
    }
  }
  return circles;
}

// A small object from its pushed points: the cells of their hull and of the points themselves
// that the laser did not see free.
std::optional<Detection> smallObject(const std::vector<Eigen::Vector2d>& pushed, const BeamEvidence& beams,
                                     const OccupancyGrid& geometry, int hiddenSteps) {
  Polygon hull = convexHull(pushed);
  std::vector<std::size_t> cells = rasterize(hull, pushed, geometry);
  std::erase_if(cells, [&](std::size_t c) { return beams.seenFree(c); });
  if (cells.empty()) return std::nullopt;
  cells = beams.growIntoUnobserved(std::move(cells), hiddenSteps);
  return Detection{DetectionKind::kCluster, std::move(hull), std::move(cells), static_cast<double>(pushed.size())};
}

// Small isolated objects among the cloud points not explained by `kept` objects.
void addSmallObjects(const std::vector<CloudPoint>& points, const std::vector<bool>& onStructure,
                     const BeamEvidence& beams, const OccupancyGrid& geometry, const ObjectDetectionParams& params,
                     std::vector<Detection>& kept) {
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
      if (auto d = smallObject(members, beams, geometry, params.hiddenSteps)) small.push_back(std::move(*d));
    }
  }
  kept.insert(kept.end(), small.begin(), small.end());
}

}  // namespace

DetectionSummary detectObjects(const TourScans& tour, const OccupancyGrid& geometry,
                               const ObjectDetectionParams& params) {
  DetectionSummary out;
  const RectangleDetector rectangleDetector(params.rectangles);
  StructureLines structure(params.structureDistanceM, params.structureExtensionM);
  PointCloud cloud(geometry.resolution());
  BeamEvidence beams(geometry);
  std::vector<Detection> rectangleCandidates;
  for (const std::vector<LaserScan>& scans : tour.byRoom) {
    RegionLineMap map;
    const LaserScan* last = nullptr;
    for (const LaserScan& scan : scans) {
      if (isKeyScan(scan, last, params)) {
        map.addScan(scan, scan.sensorPose);
        last = &scan;
      }
      cloud.add(scan);
      beams.add(scan);
    }
    out.scans += scans.size();
    out.keyScans += map.scanCount();
    out.mapLines += map.lines().size();
    for (const LineSegment& line : map.lines())
      if (line.length() >= params.structureLengthM && line.support() >= params.structureSupport) structure.add(line);
    for (const Rectangle2D& r : rectangleDetector.detect(map.lines()))
      if (r.lengthM <= params.maxAspectRatio * r.widthM)
        rectangleCandidates.push_back(shapeDetection(DetectionKind::kRectangle, rectangleOutline(r),
                                                   Eigen::Vector2d(r.pose.x, r.pose.y), r.confidence, geometry));
  }
  const std::vector<CloudPoint>& points = cloud.points();
  out.hitCells.resize(geometry.cells().size());
  for (std::size_t c = 0; c < out.hitCells.size(); ++c) out.hitCells[c] = beams.hit(c);

  std::vector<Detection> kept = keptRectangles(rectangleCandidates, beams, params.maxSeenFreeShare);

  std::vector<bool> onStructure(points.size());
  std::vector<Eigen::Vector2d> objectPoints;
  for (std::size_t i = 0; i < points.size(); ++i) {
    onStructure[i] = structure.onLine(points[i].surface);
    if (!onStructure[i]) objectPoints.push_back(points[i].surface);
  }
  const std::vector<Detection> circles = keptCircles(objectPoints, kept, beams, geometry, params);
  kept.insert(kept.end(), circles.begin(), circles.end());
  addSmallObjects(points, onStructure, beams, geometry, params, kept);
  out.detections = std::move(kept);
  return out;
}

}  // namespace rgnav
