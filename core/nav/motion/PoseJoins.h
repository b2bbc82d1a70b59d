// PoseJoins: the combinations of trajectory primitives (thesis 5.5.3: "clothoids and some
// combinations of those ... directly determined given start and end poses") that the Collision
// Avoidance uses to build candidate chains. All are closed-form geometry plus a few quadratures
// of ClothoidIntegrals: a turn's tangent length costs well under a microsecond, a G1 join (a few
// Newton steps) about 7 us, a polyline of ten targets about 12 us (Release build, one core).
//
//  - symmetricTurn: the turn between two straight lines meeting at a corner with a given
//    deflection: clothoid (curvature 0 -> k), arc of curvature k, clothoid (k -> 0), with
//    k = maxCurvature (or lower, without an arc, for a small deflection). Curvature is continuous
//    (0 at both ends), so a chain of straights and such turns has no rotational-speed jumps.
//    The classic road-design transition curve (e.g. Walton & Meek, "A controlled clothoid
//    spline", 2005).
//  - clothoidJoin: G1 Hermite interpolation: the single clothoid from one pose to another
//    (Bertolazzi & Frego, "G1 fitting with clothoids", Math. Methods Appl. Sci. 2015: Newton on
//    the generalized Fresnel integral with their initial guess). Its curvature at the ends is
//    whatever the poses demand, so a chain joined this way is only G1 (curvature may jump).
//  - smoothPolyline: the planner's target poses (0.5-2 m apart, core/nav/planning/TargetSpacing)
//    to one chain of straights and symmetric turns.
//
// The thesis' library also held conic and elliptic segments; clothoid turns and joins cover the
// same uses with continuous curvature, so those are left out.
//
// Conventions: angles in radians, positive = left (counter-clockwise); curvature in 1/m;
// sharpness (d curvature / d s) in 1/m^2. The velocity profile (TimedTrajectory) drives a
// sharpness sigma at most at sqrt(maxRotationalAcceleration / sigma) m/s, a curvature k at most
// at min(maxRotationalVelocity / k, sqrt(maxLateralAcceleration / k)): choose the shape from the
// speed you want to keep through turns.
#pragma once

#include <optional>
#include <vector>

#include "core/nav/motion/TrajectoryChain.h"

namespace rgnav {

// How sharp turns may be.
struct TurnShape {
  double maxCurvature = 2.0;  // 1/m: the tightest arc (radius 0.5 m)
  double sharpness = 4.0;     // 1/m^2: how fast the curvature builds up in the clothoids
  // smoothPolyline may raise the sharpness up to this where a turn would not fit between its
  // neighbours otherwise (the profile then slows there).
  double maxSharpness = 40.0;
};

// Throws InvalidArgumentError unless all are positive and finite and sharpness <= maxSharpness.
void validate(const TurnShape& shape);

// The symmetric clothoid-arc-clothoid turn from `start` by `deflection` (|deflection| < pi; 0
// gives no segments) with shape.maxCurvature and shape.sharpness: one to three segments.
std::vector<TrajectorySegment> symmetricTurn(const Pose2D& start, double deflection, const TurnShape& shape);

// The distance from the corner (where the straight lines before and after the turn meet) back
// to the turn's start, equal to that from the corner on to the turn's end. Grows with the
// deflection, the radius 1/maxCurvature and 1/sharpness; infinite for |deflection| >= pi.
double turnTangentLength(double deflection, const TurnShape& shape);

// The turn at a corner: the straight line from `before` through `corner` turns into the line from
// `corner` to `after`. The turn starts turnTangentLength before the corner. nullopt when a
// point coincides with the corner or the lines fold back (deflection within 1e-3 of pi); does not
// check that the turn fits between `before` and `after`.
std::optional<std::vector<TrajectorySegment>> cornerTurn(const Pose2D& before, const Pose2D& corner,
                                                         const Pose2D& after, const TurnShape& shape);

// The single clothoid from `from` to `to` with their headings (G1 Hermite). nullopt when the
// positions coincide (< 1 mm) or when its curvature anywhere exceeds maxCurvature.
std::optional<TrajectorySegment> clothoidJoin(const Pose2D& from, const Pose2D& to, double maxCurvature);

// A smooth chain from `start` through the corners of the polyline start -> targets[0] -> ... ->
// targets.back(): straights joined by symmetric turns (curvature continuous, 0 at both ends of
// the chain). The targets' headings are not used (the planner's point at the next target); the
// chain leaves `start` with start.theta (when that does not point at the first target it begins
// with a turn onto the line to it) and ends at the last target heading along the last leg. It
// cuts every corner (passing inside it), so it reaches the intermediate targets only where the
// polyline is straight. Where two turns would overlap on a short leg they are made sharper (up to
// maxSharpness) to fit. nullopt when they cannot fit even so, when the polyline folds back
// (a deflection within 1e-3 of pi) or when there are no targets. Throws InvalidArgumentError for
// a bad shape.
std::optional<TrajectoryChain> smoothPolyline(const Pose2D& start, const std::vector<Pose2D>& targets,
                                              const TurnShape& shape);

}  // namespace rgnav
