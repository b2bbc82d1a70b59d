// SOC, "last but one" and ASC (thesis 4.1.3.1-4.1.3.2; see WeightClassifiers.h).
#include "core/gateways/classify/WeightClassifiers.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

bool isIgnored(const GatewayWeightLayout& layout, GatewayClass c) {
  return std::find(layout.ignored.begin(), layout.ignored.end(), c) != layout.ignored.end();
}

// The class of the largest weight among the entries the layout does not ignore.
GatewayClass argmaxClass(const Eigen::VectorXd& weights, const GatewayWeightLayout& layout) {
  Eigen::Index best = -1;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(layout.entries.size()); ++i) {
    if (isIgnored(layout, layout.entries[static_cast<std::size_t>(i)])) continue;
    if (best < 0 || weights[i] > weights[best]) best = i;
  }
  if (best < 0) throw InvalidArgumentError("weight layout ignores every class");
  return layout.entries[static_cast<std::size_t>(best)];
}

Eigen::Index dimensionOf(const GatewayWeightLayout& layout) {
  if (layout.entries.empty()) throw InvalidArgumentError("weight layout has no entries");
  return static_cast<Eigen::Index>(layout.entries.size());
}

// The layout's weights lead every observation vector; further entries are allowed.
void checkObservations(const GatewayObservationSequence& sequence, Eigen::Index weights) {
  checkSequence(sequence, sequence.empty() ? weights : sequence.front().weights.size());
  if (sequence.front().weights.size() < weights) {
    throw InvalidArgumentError("observation vectors hold " + std::to_string(sequence.front().weights.size()) +
                               " entries, the weight layout " + std::to_string(weights));
  }
}

}  // namespace

GatewayWeightLayout thesisWeightLayout() {
  return {{kGatewayClasses.begin(), kGatewayClasses.end()}, {GatewayClass::Hallway}};
}

GatewayClass classifySingleObservation(const GatewayObservationSequence& sequence, const GatewayWeightLayout& layout,
                                       std::size_t fromEnd) {
  checkObservations(sequence, dimensionOf(layout));
  const std::size_t index = sequence.size() - 1 - std::min(fromEnd, sequence.size() - 1);
  return argmaxClass(sequence[index].weights, layout);
}

GatewayClass classifyAveragedSequence(const GatewayObservationSequence& sequence, const GatewayWeightLayout& layout,
                                      const AveragedSequenceConfig& config) {
  if (!(config.minDistance > 0.0) || !std::isfinite(config.exponent)) {
    throw InvalidArgumentError("ASC needs a positive minimum distance and a finite exponent");
  }
  const Eigen::Index dimension = dimensionOf(layout);
  checkObservations(sequence, dimension);
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(dimension);
  double totalWeight = 0.0;
  for (const GatewayObservation& o : sequence) {
    const double w = std::pow(std::max(o.distance, config.minDistance), -config.exponent);
    sum += w * o.weights.head(dimension);
    totalWeight += w;
  }
  return argmaxClass(sum / totalWeight, layout);
}

}  // namespace rgnav
