// ModelMeasures: the measures of a VLM hypothesis with respect to the general model, thesis
// 4.1.2.1.
//   Distance measure:       w_i = 1 - sqrt(|d_i - d_hw| / d_hw),  W_d = 0.25 * sum_i w_i,
//     d_i the distance between neighbouring gateway points (the four sides of the quadrangle),
//     d_hw the expected hallway width.
//   Rectangularity measure: W_r = 1 - 1/(2 pi) * sum_i |alpha_i - pi/2|,
//     alpha_i the inner angles of the quadrangle.
#pragma once

#include "core/gateways/vlm/GatewayPoints.h"

namespace rgnav {

// W_d. Throws InvalidArgumentError for a non-positive hallway width.
double distanceMeasure(const GatewayPoints& points, double hallwayWidthM);

// W_r; 1 for a rectangle. A degenerate corner (two coinciding points) counts as a zero angle.
double rectangularityMeasure(const GatewayPoints& points);

}  // namespace rgnav
