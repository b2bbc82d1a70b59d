// NarrowPassageConfig: the thresholds of the laser-based narrow-passage detector (thesis 4.2.1),
// in SI units. The thesis derives them from the robot and the building but gives no numbers;
// the defaults are ours:
//   - D_lr^min = 2 (robot radius + safety distance): "a rough estimate for D_lr^min/2 is given by
//     the sum of the robot's radius plus a security distance";
//   - D_lr^max from the widest expected door;
//   - D_NP^max, the largest distance at which an observation counts;
//   - the aperture α_NP: only a minimum (a passage right at the robot spans up to the whole field
//     of view, so no maximum applies);
//   - Δα, the half-width of the left and right ranges around a viewing direction α_m.
// Beyond the thesis (all ours): several viewing directions (every viewingStepRad across the field
// of view, not only the robot's heading), the depth the scan must see beyond the gateway line,
// that each gateway point bounds a surface (a wall, a cabinet) of some length rather than being a
// lone table or chair leg, and that at least one of them is a wall end in line with the passage
// (JambSurfaces.h).
#pragma once

#include <cmath>
#include <cstddef>

#include "core/lines/BreakpointDetector.h"

namespace rgnav {

struct NarrowPassageConfig {
  double robotRadiusM = 0.25;      // as the simulated robot (DiffDriveConfig)
  double safetyDistanceM = 0.05;   // added to the radius on either side
  double maxDoorWidthM = 2.2;      // D_lr^max: double doors and wide openings between rooms
  double maxDistanceM = 3.0;       // D_NP^max
  double minApertureRad = 5.0 * M_PI / 180.0;  // α_NP^min
  double halfRangeRad = 45.0 * M_PI / 180.0;   // Δα
  double viewingStepRad = 5.0 * M_PI / 180.0;  // spacing of the viewing directions α_m (ours)
  double minDepthBehindM = 1.0;    // open space: how far beyond the gateway line a beam must reach (ours)
  std::size_t minBeamsBehind = 2;  // beams that must reach that far (ours)
  double minJambLengthM = 0.3;     // each gateway point bounds a surface at least this long
  // A wall end continues the gateway line at least this far ... (longer than a jamb: at 0.3 m the
  // round legs of the IPA floor plans' tables, up to 0.3-0.35 m across, still passed for wall
  // ends; 0.4 m loses open cubicles' openings; docs/EVALUATION.md has the measurements)
  double minWallEndLengthM = 0.35;
  double wallEndToleranceM = 0.15; // ... within this distance of it (wall thickness seen obliquely)
  BreakpointParams surfaceBreaks{20.0 * M_PI / 180.0, 0.01};  // where surfaces end
};

template <class V>
void describe(V& v, NarrowPassageConfig& c) {
  v.field("robot_radius_m", c.robotRadiusM);
  v.field("safety_distance_m", c.safetyDistanceM);
  v.field("max_door_width_m", c.maxDoorWidthM);
  v.field("max_distance_m", c.maxDistanceM);
  v.degrees("min_aperture_deg", c.minApertureRad);
  v.degrees("half_range_deg", c.halfRangeRad);
  v.degrees("viewing_step_deg", c.viewingStepRad);
  v.field("min_depth_behind_m", c.minDepthBehindM);
  v.field("min_beams_behind", c.minBeamsBehind);
  v.field("min_jamb_length_m", c.minJambLengthM);
  v.field("min_wall_end_length_m", c.minWallEndLengthM);
  v.field("wall_end_tolerance_m", c.wallEndToleranceM);
  v.section("surface_breaks", c.surfaceBreaks);
}

// D_lr^min = 2 (robotRadiusM + safetyDistanceM).
double minPassageWidthM(const NarrowPassageConfig& config);

// Throws ConfigError naming the first value out of range (non-positive or non-finite sizes,
// D_lr^max not above D_lr^min, angles outside (0, pi], no beam required behind the line, a
// breakpoint angle outside (0, pi/2)).
void validate(const NarrowPassageConfig& config);

}  // namespace rgnav
