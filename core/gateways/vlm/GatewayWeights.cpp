// Weights per gateway class; see GatewayWeights.h.
#include "core/gateways/vlm/GatewayWeights.h"

namespace rgnav {

double classFreespace(GatewayClass gatewayClass, const SectorFreespace& fsm) {
  const GatewayOpenings open = openingsOf(gatewayClass);
  const auto measure = [&fsm](bool isOpen, Sector s) { return isOpen ? fsm.over(s) : fsm.on(s); };
  return measure(open.left, Sector::Left) + measure(open.straight, Sector::Front) + measure(open.right, Sector::Right);
}

std::vector<double> gatewayWeights(double distanceMeasure, double rectangularityMeasure, const SectorFreespace& fsm,
                                   const WeightParams& params) {
  const double general = params.fVlm / 2.0 * (distanceMeasure + rectangularityMeasure);
  std::vector<double> weights;
  weights.reserve(kGatewayClasses.size());
  for (const GatewayClass c : kGatewayClasses) weights.push_back(general + params.fGw / 3.0 * classFreespace(c, fsm));
  return weights;
}

}  // namespace rgnav
