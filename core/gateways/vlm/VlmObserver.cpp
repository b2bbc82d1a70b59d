// The per-scan pipeline from ranges to observation vectors; see VlmObserver.h.
#include "core/gateways/vlm/VlmObserver.h"

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
  const auto through = [](const Eigen::Vector2d& from, const Eigen::Vector2d& to) -> std::optional<PlanarLine> {
    const Eigen::Vector2d d = to - from;
    if (!(d.norm() > 1e-6)) return std::nullopt;
    return PlanarLine{from, d.normalized()};
  };
  const auto left = through(points[kHiddenLeft], points[kFrontLeft]);
  const auto right = through(points[kHiddenRight], points[kFrontRight]);
  const auto front = through(points[kFrontRight], points[kFrontLeft]);
  const auto hidden = through(points[kHiddenRight], points[kHiddenLeft]);
  if (!left || !right || !front || !hidden) return std::nullopt;
  VlmHypothesis h;
  h.left = *left;
  h.right = *right;
  h.front = *front;
  h.hidden = *hidden;
  h.gatewayPoints = points;
  return measured(h, scan);
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
