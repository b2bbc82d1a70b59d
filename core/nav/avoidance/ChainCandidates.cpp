// Candidate chains for the Collision Avoidance (see ChainCandidates.h).
#include "core/nav/avoidance/ChainCandidates.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/nav/motion/PoseJoins.h"

namespace rgnav {

namespace {

// Joins below this length are left out (the targets coincide).
constexpr double kMinJoinM = 1e-3;
// Slices shorter than this are left out (a pivot by a degree is some 2e-5 m long).
constexpr double kMinSliceM = 1e-9;
// Deviations shift up to this many of the first targets.
constexpr std::size_t kDeviatedTargets = 3;
// Pivots (turning on the spot) below this angle are left out.
constexpr double kMinPivotRad = 0.05;

TurnShape shapeOf(const CandidateConfig& config, double sharpness) {
  return {config.turnMaxCurvaturePerM, sharpness, config.turnMaxSharpnessPerM2};
}

// The targets up to the first that lies horizonM or farther along the polyline from `start`.
std::vector<Pose2D> withinHorizon(const Pose2D& start, std::span<const Pose2D> targets, double horizonM) {
  std::vector<Pose2D> out;
  double along = 0.0;
  Pose2D previous = start;
  for (const Pose2D& target : targets) {
    along += std::hypot(target.x - previous.x, target.y - previous.y);
    out.push_back(target);
    if (along >= horizonM) break;
    previous = target;
  }
  return out;
}

// Turn by `deflection`, then straight on to `length` in all.
std::optional<TrajectoryChain> fanChain(const Pose2D& start, double deflection, double length, const TurnShape& shape) {
  TrajectoryChain chain(symmetricTurn(start, deflection, shape));
  const double rest = length - chain.length();
  if (rest > kMinJoinM) chain.append(TrajectorySegment{chain.empty() ? start : chain.end(), rest, 0.0, 0.0});
  if (chain.empty()) return std::nullopt;
  return chain;
}

}  // namespace

TrajectorySegment pivot(const Pose2D& at, double angle) {
  return {at, std::abs(angle) / kPivotCurvature, angle > 0.0 ? kPivotCurvature : -kPivotCurvature, 0.0};
}

std::vector<Candidate> candidateChains(const ChainStart& start, std::span<const Pose2D> targets,
                                       const CandidateConfig& config) {
  std::vector<Candidate> out;
  if (targets.empty()) return out;
  // Fast, gentle turns for the path; sharp ones (slower, tighter) for it and the manoeuvres.
  const TurnShape gentle = shapeOf(config, config.turnSharpnessPerM2);
  const TurnShape shape = shapeOf(config, config.manoeuvreSharpnessPerM2);
  const std::vector<Pose2D> ahead = withinHorizon(start.pose, targets, config.horizonM);
  for (const TurnShape& s : {gentle, shape})
    if (auto chain = smoothPolyline(start.pose, ahead, s)) out.push_back({Candidate::Kind::Path, std::move(*chain)});
  // Deviations: the first one, two or three targets shifted sideways (across their headings,
  // which point along the path) by the same offset: around an obstacle on the path, then back.
  const Pose2D& first = ahead.front();
  // (Never the goal: it is where the robot must end up.)
  const std::size_t shiftable = ahead.size() == targets.size() ? ahead.size() - 1 : ahead.size();
  for (std::size_t run = 1; run <= std::min(kDeviatedTargets, shiftable); ++run)
    for (std::size_t k = 1; k <= config.lateralCount; ++k)
      for (const double side : {1.0, -1.0}) {
        const double offset = side * static_cast<double>(k) * config.lateralStepM;
        std::vector<Pose2D> shifted = ahead;
        for (std::size_t i = 0; i < run; ++i) {
          shifted[i].x -= offset * std::sin(shifted[i].theta);
          shifted[i].y += offset * std::cos(shifted[i].theta);
        }
        if (auto chain = smoothPolyline(start.pose, shifted, shape))
          out.push_back({Candidate::Kind::Deviation, std::move(*chain)});
      }
  if (start.standing && config.pivotCount > 0) {
    // Standing: turn on the spot towards the first target, or by steps either way, then the path.
    std::vector<double> angles{normalizeAngle(std::atan2(first.y - start.pose.y, first.x - start.pose.x) - start.pose.theta)};
    for (std::size_t k = 1; k <= config.pivotCount; ++k)
      for (const double side : {1.0, -1.0})
        angles.push_back(side * std::min(M_PI, static_cast<double>(k) * config.pivotStepRad));
    for (const double angle : angles) {
      if (std::abs(angle) < kMinPivotRad) continue;
      const TrajectorySegment turn = pivot(start.pose, angle);
      auto rest = smoothPolyline(turn.end(), ahead, shape);
      if (!rest) continue;
      TrajectoryChain chain({turn});
      for (const TrajectorySegment& segment : rest->segments()) chain.append(segment);
      out.push_back({Candidate::Kind::Pivot, std::move(chain)});
    }
  }
  for (std::size_t i = 0; i < config.fanCount; ++i) {
    const double deflection =
        config.fanCount == 1 ? 0.0
                             : config.fanMaxDeflectionRad * (2.0 * static_cast<double>(i) / static_cast<double>(config.fanCount - 1) - 1.0);
    if (auto chain = fanChain(start.pose, deflection, config.fanLengthM, shape))
      out.push_back({Candidate::Kind::Fan, std::move(*chain)});
  }
  return out;
}

TrajectoryChain sliceChain(const TrajectoryChain& chain, double from, double to) {
  from = std::max(from, 0.0);
  to = std::min(to, chain.length());
  TrajectoryChain out;
  double segmentStart = 0.0;
  for (const TrajectorySegment& segment : chain.segments()) {
    const double a = std::max(from, segmentStart) - segmentStart;
    const double b = std::min(to, segmentStart + segment.length) - segmentStart;
    if (b - a > kMinSliceM)
      out.append(TrajectorySegment{segment.poseAt(a), b - a, segment.curvatureAt(a), segment.sharpness});
    segmentStart += segment.length;
  }
  return out;
}

}  // namespace rgnav
