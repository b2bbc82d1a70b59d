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
  for (const VlmHypothesis& h : hypotheses) {
    VlmObservation o;
    o.hypothesis = h;
    o.distanceM = gatewayCentre(h.gatewayPoints).norm();
    o.distanceMeasure = distanceMeasure(h.gatewayPoints, params_.hypotheses.hallwayWidthM);
    o.rectangularityMeasure = rectangularityMeasure(h.gatewayPoints);
    o.freespace = freespaceMeasures(h, scan, params_.freespace);
    o.weights = gatewayWeights(o.distanceMeasure, o.rectangularityMeasure, o.freespace, params_.weights);
    o.observation = observationVector(o.weights, o.distanceMeasure, o.rectangularityMeasure, o.freespace);
    observations.push_back(std::move(o));
  }
  return observations;
}

}  // namespace rgnav
