// Checks and matrix view of observation sequences (see GatewayObservation.h).
#include "core/gateways/classify/GatewayObservation.h"

#include <cmath>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {

GatewayObservationSequence makeObservationSequence(const std::vector<double>& distances,
                                                   const std::vector<std::vector<double>>& weights) {
  if (distances.size() != weights.size()) {
    throw InvalidArgumentError(std::to_string(distances.size()) + " distances for " + std::to_string(weights.size()) +
                               " weight vectors");
  }
  GatewayObservationSequence sequence;
  for (std::size_t t = 0; t < distances.size(); ++t) {
    sequence.push_back({distances[t], Eigen::Map<const Eigen::VectorXd>(weights[t].data(),
                                                                        static_cast<Eigen::Index>(weights[t].size()))});
  }
  return sequence;
}

void checkSequence(const GatewayObservationSequence& sequence, Eigen::Index dimension) {
  if (sequence.empty()) throw InvalidArgumentError("observation sequence is empty");
  for (std::size_t t = 0; t < sequence.size(); ++t) {
    const GatewayObservation& o = sequence[t];
    const std::string where = "observation " + std::to_string(t) + ": ";
    if (o.weights.size() != dimension) {
      throw InvalidArgumentError(where + std::to_string(o.weights.size()) + " weights, expected " +
                                 std::to_string(dimension));
    }
    if (!o.weights.allFinite()) throw InvalidArgumentError(where + "weight is not finite");
    if (!std::isfinite(o.distance) || o.distance < 0.0) {
      throw InvalidArgumentError(where + "distance is negative or not finite");
    }
  }
}

Eigen::MatrixXd weightMatrix(const GatewayObservationSequence& sequence, Eigen::Index dimension) {
  checkSequence(sequence, dimension);
  Eigen::MatrixXd matrix(dimension, static_cast<Eigen::Index>(sequence.size()));
  for (std::size_t t = 0; t < sequence.size(); ++t) matrix.col(static_cast<Eigen::Index>(t)) = sequence[t].weights;
  return matrix;
}

}  // namespace rgnav
