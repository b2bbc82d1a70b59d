// Virtual line grouping into VLM hypotheses; see VlmHypotheses.h.
#include "core/gateways/vlm/VlmHypotheses.h"

#include <algorithm>
#include <optional>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

const Eigen::Vector2d kRobot = Eigen::Vector2d::Zero();

struct Parallels {
  PlanarLine left, right;
  Eigen::Vector2d axis;    // unit, forward along the hallway
  Eigen::Vector2d toLeft;  // unit, axis turned left
};

void validate(const VlmHypothesisParams& p) {
  if (!(p.hallwayWidthM > 0.0)) throw InvalidArgumentError("VLM hypotheses: the hallway width must be positive");
  if (!(p.maxParallelAngleRad >= 0.0) || !(p.maxRightAngleErrorRad >= 0.0 && p.maxRightAngleErrorRad < M_PI / 2) ||
      !(p.widthTolerance >= 0.0) || !(p.maxSingularityOffsetM >= 0.0) || !(p.duplicateToleranceM >= 0.0))
    throw InvalidArgumentError("VLM hypotheses: limits must be non-negative, right-angle error below 90 degrees");
}

bool widthMatches(double spacing, const VlmHypothesisParams& p) {
  return std::fabs(spacing - p.hallwayWidthM) <= p.widthTolerance * p.hallwayWidthM;
}

// a and b as left and right line if they are parallel, the robot lies between them and their
// spacing matches the hallway width.
std::optional<Parallels> parallels(const PlanarLine& a, const PlanarLine& b, const VlmHypothesisParams& p) {
  if (angleBetween(a, b) > p.maxParallelAngleRad) return std::nullopt;
  PlanarLine first = a, second = b;
  if (second.direction.dot(first.direction) < 0.0) second.direction = -second.direction;
  Eigen::Vector2d axis = (first.direction + second.direction).normalized();
  if (axis.x() < 0.0) {
    axis = -axis;
    first.direction = -first.direction;
    second.direction = -second.direction;
  }
  const double offsetFirst = first.signedOffset(kRobot), offsetSecond = second.signedOffset(kRobot);
  if (offsetFirst * offsetSecond >= 0.0) return std::nullopt;  // the robot is not in between
  const Eigen::Vector2d toLeft(-axis.y(), axis.x());
  if (!widthMatches(std::fabs(toLeft.dot(first.point - second.point)), p)) return std::nullopt;
  // The robot lies to the right of the left line.
  return offsetFirst < 0.0 ? Parallels{first, second, axis, toLeft} : Parallels{second, first, axis, toLeft};
}

// f as the front line of the parallels: about perpendicular, both crossings in front of the robot.
std::optional<PlanarLine> frontLine(const PlanarLine& f, const Parallels& pair, const VlmHypothesisParams& p) {
  if (angleBetween(f, {kRobot, pair.axis}) < M_PI / 2 - p.maxRightAngleErrorRad) return std::nullopt;
  PlanarLine front = f;
  if (front.direction.dot(pair.toLeft) < 0.0) front.direction = -front.direction;
  const auto fl = intersect(front, pair.left), fr = intersect(front, pair.right);
  if (!fl || !fr || pair.axis.dot(*fl) <= 0.0 || pair.axis.dot(*fr) <= 0.0) return std::nullopt;
  return front;
}

std::optional<VlmHypothesis> assemble(const Parallels& pair, const PlanarLine& front, const PlanarLine& hidden,
                                      HiddenLineSource source) {
  const auto hl = intersect(hidden, pair.left), fl = intersect(front, pair.left);
  const auto fr = intersect(front, pair.right), hr = intersect(hidden, pair.right);
  if (!hl || !fl || !fr || !hr) return std::nullopt;
  return VlmHypothesis{pair.left, pair.right, front, hidden, source, {*hl, *fl, *fr, *hr}};
}

void addUnlessDuplicate(std::vector<VlmHypothesis>& out, const std::optional<VlmHypothesis>& h, double tolerance) {
  if (!h) return;
  const bool duplicate = std::any_of(out.begin(), out.end(), [&](const VlmHypothesis& o) {
    return largestPointDistance(o.gatewayPoints, h->gatewayPoints) <= tolerance;
  });
  if (!duplicate) out.push_back(*h);
}

}  // namespace

std::vector<VlmHypothesis> vlmHypotheses(const std::vector<VirtualLine>& lines,
                                         const std::vector<Eigen::Vector2d>& singularities,
                                         const VlmHypothesisParams& params) {
  validate(params);
  std::vector<VlmHypothesis> singular, byWidth;
  for (std::size_t a = 0; a < lines.size(); ++a) {
    for (std::size_t b = a + 1; b < lines.size(); ++b) {
      const auto pair = parallels(lines[a].line, lines[b].line, params);
      if (!pair) continue;
      for (std::size_t f = 0; f < lines.size(); ++f) {
        if (f == a || f == b) continue;
        const auto front = frontLine(lines[f].line, *pair, params);
        if (!front) continue;
        for (const Eigen::Vector2d& s : singularities) {
          const bool nearSide = std::fabs(pair->left.signedOffset(s)) <= params.maxSingularityOffsetM ||
                                std::fabs(pair->right.signedOffset(s)) <= params.maxSingularityOffsetM;
          // The front line's left normal points back towards the robot.
          const double spacing = front->signedOffset(s);
          if (nearSide && spacing > 0.0 && widthMatches(spacing, params))
            addUnlessDuplicate(singular,
                               assemble(*pair, *front, front->parallelThrough(s), HiddenLineSource::DepthSingularity),
                               params.duplicateToleranceM);
        }
        addUnlessDuplicate(byWidth,
                           assemble(*pair, *front, front->shifted(params.hallwayWidthM), HiddenLineSource::HallwayWidth),
                           params.duplicateToleranceM);
      }
    }
  }
  for (const VlmHypothesis& h : byWidth) addUnlessDuplicate(singular, h, params.duplicateToleranceM);
  return singular;
}

}  // namespace rgnav
