// VlmObserver: one laser scan to observation vectors, thesis 4.1.1-4.1.2: the line scan
// (core/lines LineExtractor), virtual lines, depth singularities, VLM hypotheses, and per
// hypothesis the general measures W_d and W_r, the freespace measures per sector, the
// weights W(GW, VLM) per gateway class and the observation vector (ObservationVector.h).
// Everything in the sensor frame of the scan. observeAt measures a hypothesis known from earlier
// scans (the tracker's coasting, HypothesisTracker.h) in a scan that did not re-detect it.
#pragma once

#include <optional>
#include <vector>

#include "core/common/SensorData.h"
#include "core/gateways/vlm/FreespaceMeasures.h"
#include "core/gateways/vlm/GatewayWeights.h"
#include "core/gateways/vlm/ObservationVector.h"
#include "core/gateways/vlm/VirtualLines.h"
#include "core/gateways/vlm/VlmHypotheses.h"
#include "core/lines/LineExtractor.h"

namespace rgnav {

struct VlmObserverParams {
  LineExtractorParams lineExtraction;
  VirtualLineParams virtualLines;
  double minSingularityJumpM = 0.5;  // Δd_min (the thesis gives no value)
  VlmHypothesisParams hypotheses;    // holds d_hw, also used by W_d
  FreespaceParams freespace;
  WeightParams weights;
};

template <class V>
void describe(V& v, VlmObserverParams& c) {
  v.section("line_extraction", c.lineExtraction);
  v.section("virtual_lines", c.virtualLines);
  v.field("min_singularity_jump_m", c.minSingularityJumpM);
  v.section("hypotheses", c.hypotheses);
  v.section("freespace", c.freespace);
  v.section("weights", c.weights);
}

struct VlmObservation {
  VlmHypothesis hypothesis;
  double distanceM = 0.0;  // from the sensor to the gateway centre
  double distanceMeasure = 0.0;        // W_d
  double rectangularityMeasure = 0.0;  // W_r
  SectorFreespace freespace;
  std::vector<double> weights;  // W(GW, VLM) per class of kGatewayClasses
  std::vector<double> observation;  // weights, then measures (ObservationVector.h)
};

class VlmObserver {
 public:
  // Throws InvalidArgumentError for parameters that can never work.
  explicit VlmObserver(const VlmObserverParams& params = {});

  std::vector<VlmObservation> observe(const LaserScan& scan) const;
  // The observation of the VLM whose gateway points (in the scan's sensor frame) are `points`:
  // its four lines run through the points (left and right from the hidden to the front points,
  // front and hidden from right to left), as those of a detected hypothesis do. None when two
  // points coincide, when a point lies outside the scan's field of view or beyond its maximum
  // range, or when a sector holds no beam: the scan cannot see that VLM.
  std::optional<VlmObservation> observeAt(const GatewayPoints& points, const LaserScan& scan) const;

  const VlmObserverParams& params() const { return params_; }

 private:
  VlmObservation measured(const VlmHypothesis& hypothesis, const LaserScan& scan) const;

  VlmObserverParams params_;
  LineExtractor extractor_;
};

}  // namespace rgnav
