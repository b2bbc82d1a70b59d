// ObservationVector: the observation vector of a VLM hypothesis that the tracker collects into
// sequences and the classifiers of thesis 4.1.3 read (4.1.2.3: "As a result we obtain an
// observation vector for each VLM hypothesis"). Its first entries are the weights W(GW, VLM)
// per class of kGatewayClasses, exactly the thesis' vector, which SOC and ASC read; after them
// follow the measures the weights are made of (4.1.2.1, 4.1.2.2): W_d, W_r, then W_on^S of the
// left, front and right sector, then W_over^S of the left, front and right sector.
// Where we differ: the thesis' HMMs see the weights only. The eight weights are one affine
// function of four numbers - the sum f_vlm/2 (W_d + W_r) + f_gw/3 sum_S W_on^S and, per sector,
// W_over^S - W_on^S - so they cannot tell a sector where neither measure holds (beams ending on
// clutter between the line and l_par) from one where both do, nor W_d from W_r. The HMMs here
// read the whole vector, which tells clutter between the line and l_par from a real sector
// (docs/EVALUATION.md has the error counts).
#pragma once

#include <cstddef>
#include <vector>

#include "core/gateways/classes/GatewayClass.h"
#include "core/gateways/vlm/FreespaceMeasures.h"

namespace rgnav {

inline constexpr std::size_t kMeasureCount = 2 + 2 * kSectorCount;  // W_d, W_r, on and over per sector
inline constexpr std::size_t kObservationSize = kGatewayClasses.size() + kMeasureCount;

// `weights` (one per class of kGatewayClasses) followed by the measures. Throws
// InvalidArgumentError for a weight vector of another size.
std::vector<double> observationVector(const std::vector<double>& weights, double distanceMeasure,
                                      double rectangularityMeasure, const SectorFreespace& fsm);

}  // namespace rgnav
