// TrackedObservations: the bridge from the VLM hypothesis tracker (thesis 4.1.2.3) to the
// classifiers of 4.1.3: a tracked sequence's plain vectors as a GatewayObservationSequence, the
// input of the weight classifiers and the gateway HMMs. Used by the GatewayDetection server and
// the crossing evaluation alike.
#pragma once

#include "core/gateways/classify/GatewayObservation.h"
#include "core/gateways/vlm/HypothesisTracker.h"

namespace rgnav {

// Observation t is (tracked.distances[t], tracked.observations[t]). Throws InvalidArgumentError
// if the tracked sequence holds a different number of distances and observation vectors.
GatewayObservationSequence toObservationSequence(const TrackedSequence& tracked);

}  // namespace rgnav
