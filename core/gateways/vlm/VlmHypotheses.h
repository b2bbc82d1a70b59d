// VlmHypotheses: virtual line grouping, thesis 4.1.1.2. Candidates for the virtual left and
// right line are pairs of parallel virtual lines with the robot in between; virtual front lines
// cross such a pair approximately at right angles in front of the robot; the hidden line is
// parallel to the front line, through a depth singularity close to the left or right line, or
// (for scans without a usable singularity, e.g. in clutter) one hallway width d_hw before the
// front line. VLMs whose gateway points all coincide within duplicateToleranceM are kept once
// (singularity-based ones first). The robot is the origin of the sensor frame, heading along +x.
// Our additions, where the thesis gives no rule: the spacing of the parallels and of the hidden
// and front line must lie within (1 ± widthTolerance) d_hw (W_d weighs the deviation; this only
// bounds the number of hypotheses), and the singularity must lie on the robot's side of the
// front line. The thesis gives no values for the limits below; these are ours.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "core/gateways/vlm/GatewayPoints.h"
#include "core/gateways/vlm/PlanarLine.h"
#include "core/gateways/vlm/VirtualLines.h"

namespace rgnav {

struct VlmHypothesisParams {
  double hallwayWidthM = 2.0;                          // d_hw, the expected hallway width
  double maxParallelAngleRad = 8.0 * M_PI / 180.0;     // left vs. right line
  double maxRightAngleErrorRad = 10.0 * M_PI / 180.0;  // front line vs. the parallels
  double widthTolerance = 0.5;                         // fraction of d_hw, see above
  double maxSingularityOffsetM = 0.25;                 // depth singularity from the left/right line
  double duplicateToleranceM = 0.25;                   // identical VLMs
};

template <class V>
void describe(V& v, VlmHypothesisParams& c) {
  v.field("hallway_width_m", c.hallwayWidthM);
  v.degrees("max_parallel_angle_deg", c.maxParallelAngleRad);
  v.degrees("max_right_angle_error_deg", c.maxRightAngleErrorRad);
  v.field("width_tolerance", c.widthTolerance);
  v.field("max_singularity_offset_m", c.maxSingularityOffsetM);
  v.field("duplicate_tolerance_m", c.duplicateToleranceM);
}

enum class HiddenLineSource { DepthSingularity, HallwayWidth };

// Lines in the sensor frame; left and right point forward (away from the robot), front and
// hidden from the right to the left line.
struct VlmHypothesis {
  PlanarLine left, right, front, hidden;
  HiddenLineSource hiddenSource = HiddenLineSource::HallwayWidth;
  GatewayPoints gatewayPoints;
};

// Throws InvalidArgumentError for a non-positive width, negative limits or right-angle limits
// of 90 degrees or more.
std::vector<VlmHypothesis> vlmHypotheses(const std::vector<VirtualLine>& lines,
                                         const std::vector<Eigen::Vector2d>& singularities,
                                         const VlmHypothesisParams& params = {});

}  // namespace rgnav
