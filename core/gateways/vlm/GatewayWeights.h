// GatewayWeights: the weights of a VLM hypothesis per gateway class, thesis 4.1.2.3,
//   W(GW, VLM) = f_vlm / 2 * (W_d + W_r) + f_gw / 3 * sum_{i=1..3} W_FSM^{S_i}(GW),
// where the class decides per sector which freespace measure applies: Over Line where a
// hallway leaves the gateway area on that side (GatewayClass openings), On Line where a wall
// closes it. One weight per class of kGatewayClasses, in that order, including Deadend (all
// sectors On Line) and Hallway (front Over Line, sides On Line): the observation vector.
// The thesis gives no values for f_vlm and f_gw; ours make W at most 1.
#pragma once

#include <vector>

#include "core/gateways/classes/GatewayClass.h"
#include "core/gateways/vlm/FreespaceMeasures.h"

namespace rgnav {

struct WeightParams {
  double fVlm = 0.5;  // f_vlm, general model
  double fGw = 0.5;   // f_gw, gateway-specific measures
};

template <class V>
void describe(V& v, WeightParams& c) {
  v.field("f_vlm", c.fVlm);
  v.field("f_gw", c.fGw);
}

// sum_i W_FSM^{S_i}(GW) for one class.
double classFreespace(GatewayClass gatewayClass, const SectorFreespace& fsm);

// The observation vector: W(GW, VLM) for every class of kGatewayClasses.
std::vector<double> gatewayWeights(double distanceMeasure, double rectangularityMeasure, const SectorFreespace& fsm,
                                   const WeightParams& params = {});

}  // namespace rgnav
