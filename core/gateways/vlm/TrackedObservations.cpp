// Tracked VLM sequences as classifier input; see TrackedObservations.h.
#include "core/gateways/vlm/TrackedObservations.h"

namespace rgnav {

GatewayObservationSequence toObservationSequence(const TrackedSequence& tracked) {
  return makeObservationSequence(tracked.distances, tracked.observations);
}

}  // namespace rgnav
