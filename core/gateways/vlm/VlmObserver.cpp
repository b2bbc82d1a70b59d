// The per-scan pipeline from ranges to observation vectors; see VlmObserver.h.
#include "core/gateways/vlm/VlmObserver.h"

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"
#include "core/gateways/vlm/DepthSingularities.h"
#include "core/gateways/vlm/ModelMeasures.h"

namespace rgnav {

VlmObserver::VlmObserver(const VlmObserverParams& params) : params_(params), extractor_(params.lineExtraction) {
  if (!(params.minSingularityJumpM > 0.0))
    throw InvalidArgumentError("VLM observer: the depth singularity jump must be positive");
  if (!(params.hypotheses.hallwayWidthM > 0.0))
    throw InvalidArgumentError("VLM observer: the hallway width must be positive");
}

std::vector<VlmObservation> VlmObserver::observe(const LaserScan& scan) const {
  const std::vector<VirtualLine> lines = groupVirtualLines(extractor_.extract(scan, Pose2D{}, 0), params_.virtualLines);
  const std::vector<VlmHypothesis> hypotheses =
      vlmHypotheses(lines, depthSingularities(scan, params_.minSingularityJumpM), params_.hypotheses);
  std::vector<VlmObservation> observations;
  observations.reserve(hypotheses.size());
  for (const VlmHypothesis& h : hypotheses) observations.push_back(measured(h, scan));
  return observations;
}

std::optional<VlmObservation> VlmObserver::observeAt(const GatewayPoints& points, const LaserScan& scan) const {
  if (scan.ranges.empty()) return std::nullopt;
  const double lastBearing = scan.startAngle + scan.angleIncrement * static_cast<double>(scan.ranges.size() - 1);
  const double lowBearing = std::min(scan.startAngle, lastBearing), highBearing = std::max(scan.startAngle, lastBearing);
  for (const Eigen::Vector2d& p : points) {
    const double bearing = std::atan2(p.y(), p.x());
    if (p.norm() > scan.maxRange || bearing < lowBearing || bearing > highBearing) return std::nullopt;
  }
  const auto left = lineThrough(points[kHiddenLeft], points[kFrontLeft]);
  const auto right = lineThrough(points[kHiddenRight], points[kFrontRight]);
  const auto front = lineThrough(points[kFrontRight], points[kFrontLeft]);
  const auto hidden = lineThrough(points[kHiddenRight], points[kHiddenLeft]);
  if (!left || !right || !front || !hidden) return std::nullopt;
  VlmHypothesis h;
  h.left = *left;
  h.right = *right;
  h.front = *front;
  h.hidden = *hidden;
  h.gatewayPoints = points;
  VlmObservation o = measured(h, scan);
  for (const std::size_t beams : o.freespace.beams)
    if (beams == 0) return std::nullopt;
  return o;
}

VlmObservation VlmObserver::measured(const VlmHypothesis& h, const LaserScan& scan) const {
  VlmObservation o;
  o.hypothesis = h;
  o.distanceM = gatewayCentre(h.gatewayPoints).norm();
  o.distanceMeasure = distanceMeasure(h.gatewayPoints, params_.hypotheses.hallwayWidthM);
  o.rectangularityMeasure = rectangularityMeasure(h.gatewayPoints);
  o.freespace = freespaceMeasures(h, scan, params_.freespace);
  o.weights = gatewayWeights(o.distanceMeasure, o.rectangularityMeasure, o.freespace, params_.weights);
  o.observation = observationVector(o.weights, o.distanceMeasure, o.rectangularityMeasure, o.freespace);
  return o;
}

}  // namespace rgnav
