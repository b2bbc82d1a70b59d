// The weight-based gateway classifiers of thesis 4.1.3.1 and 4.1.3.2: the single observation
// classifier (SOC) on the last observation or on the one before it ("last but one", table 4.2),
// and the averaged sequence classifier (ASC) with weights inversely proportional to distance.
// Both choose the class of the largest weight and skip the classes a layout ignores (the thesis
// ignores Hallway, whose weights are large wherever there is open space ahead).
// Differences: the ASC weight is 1 / max(d, minDistance)^exponent, so the thesis' 1/d is
// exponent 1 and a zero distance stays finite; ties go to the first entry of the layout.
#pragma once

#include <cstddef>
#include <vector>

#include "core/gateways/classes/GatewayClass.h"
#include "core/gateways/classify/GatewayObservation.h"

namespace rgnav {

// The first entries.size() entries of an observation vector are its weights; entries after them
// (the measures of core/gateways/vlm ObservationVector.h) are not read.
struct GatewayWeightLayout {
  std::vector<GatewayClass> entries;  // the class measured by each weight entry, in order
  std::vector<GatewayClass> ignored;  // classes never chosen
};

// The eight classes in kGatewayClasses order, Hallway ignored (thesis 4.1.3.1).
GatewayWeightLayout thesisWeightLayout();

// SOC: the class of the maximum weight in the observation `fromEnd` places before the last one
// (0: last observation, 1: last but one); a shorter sequence uses its first observation.
GatewayClass classifySingleObservation(const GatewayObservationSequence& sequence, const GatewayWeightLayout& layout,
                                       std::size_t fromEnd = 0);

struct AveragedSequenceConfig {
  double exponent = 1.0;     // weight of an observation = 1 / max(distance, minDistance)^exponent
  double minDistance = 0.1;  // metres
};

// ASC: the class of the maximum entry of the distance-weighted mean weight vector.
GatewayClass classifyAveragedSequence(const GatewayObservationSequence& sequence, const GatewayWeightLayout& layout,
                                      const AveragedSequenceConfig& config = {});

}  // namespace rgnav
