// The observation vector: weights, then measures; see ObservationVector.h.
#include "core/gateways/vlm/ObservationVector.h"

#include <string>

#include "core/common/Errors.h"

namespace rgnav {

std::vector<double> observationVector(const std::vector<double>& weights, double distanceMeasure,
                                      double rectangularityMeasure, const SectorFreespace& fsm) {
  if (weights.size() != kGatewayClasses.size())
    throw InvalidArgumentError("observation vector: " + std::to_string(weights.size()) + " weights, expected " +
                               std::to_string(kGatewayClasses.size()));
  std::vector<double> vector = weights;
  vector.reserve(kObservationSize);
  vector.push_back(distanceMeasure);
  vector.push_back(rectangularityMeasure);
  vector.insert(vector.end(), fsm.onLine.begin(), fsm.onLine.end());
  vector.insert(vector.end(), fsm.overLine.begin(), fsm.overLine.end());
  return vector;
}

}  // namespace rgnav
