// Labelling of the tracked sequences of one approach; see SequenceLabelling.h.
#include "tests/eval/crossings/SequenceLabelling.h"

namespace rgnav {

std::vector<LabelledTrack> labelApproach(const std::vector<TrackedSequence>& sequences, GatewayClass scenarioClass,
                                         double width, const LabelParams& params) {
  const GatewayPoints truth = squareGatewayArea(width);
  const bool hasGateway = scenarioClass != GatewayClass::Hallway;
  std::vector<LabelledTrack> labelled;
  const TrackedSequence* best = nullptr;
  for (const TrackedSequence& s : sequences) {
    if (s.distances.size() < params.minObservations) continue;
    if (!hasGateway || gatewayCentre(s.gatewayPoints).norm() > params.counterFraction * width) {
      labelled.push_back({GatewayClass::Hallway, s});
    } else if (largestPointDistance(s.gatewayPoints, truth) <= params.matchFraction * width &&
               (!best || s.distances.size() > best->distances.size())) {
      best = &s;
    }
  }
  if (best) labelled.push_back({scenarioClass, *best});
  return labelled;
}

}  // namespace rgnav
