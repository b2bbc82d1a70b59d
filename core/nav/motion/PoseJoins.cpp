// PoseJoins: symmetric clothoid turns, the G1 Hermite clothoid of Bertolazzi & Frego and the
// polyline smoothing built on them (see the header).
#include "core/nav/motion/PoseJoins.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/Errors.h"
#include "core/nav/motion/ClothoidIntegrals.h"

namespace rgnav {

namespace {

constexpr double kFoldBack = M_PI - 1e-3;  // rad: sharper corners fold the path back
constexpr double kNoTurn = 1e-9;           // rad: straight on

// The parts of a symmetric turn by |deflection|: the peak curvature, each clothoid's length and
// the arc's length.
struct TurnParts {
  double peak;
  double clothoid;
  double arc;
};

TurnParts turnParts(double deflection, const TurnShape& shape) {
  const double a = std::abs(deflection);
  const double k = shape.maxCurvature, sigma = shape.sharpness;
  if (k * k / sigma >= a) {  // the two clothoids alone turn far enough
    const double peak = std::sqrt(a * sigma);
    return {peak, peak / sigma, 0.0};
  }
  return {k, k / sigma, (a - k * k / sigma) / k};
}

struct Point {
  double x;
  double y;
};

double headingOf(Point from, Point to) { return std::atan2(to.y - from.y, to.x - from.x); }
double distance(Point a, Point b) { return std::hypot(b.x - a.x, b.y - a.y); }

// The sharpness in [shape.sharpness, shape.maxSharpness] whose turn has a tangent length of at
// most `allowed`, by bisection on its logarithm (the tangent length falls as the sharpness grows);
// nullopt when even the sharpest turn is longer.
std::optional<double> sharpnessFitting(double deflection, const TurnShape& shape, double allowed) {
  TurnShape trial = shape;
  trial.sharpness = shape.maxSharpness;
  if (turnTangentLength(deflection, trial) > allowed) return std::nullopt;
  double lo = std::log(shape.sharpness), hi = std::log(shape.maxSharpness);
  for (int i = 0; i < 40; ++i) {
    trial.sharpness = std::exp(0.5 * (lo + hi));
    (turnTangentLength(deflection, trial) > allowed ? lo : hi) = std::log(trial.sharpness);
  }
  return std::exp(hi);
}

// A corner of the polyline and its turn.
struct Corner {
  Point at;
  double deflection = 0.0;
  double tangent = 0.0;
  double sharpness = 0.0;
  bool fixed = false;  // the turn out of the start heading: its size is set
};

// The corner ahead of the start on the start heading from which a turn starting at the start
// itself reaches the line to `next` (a fixed point: the corner's distance is the turn's tangent
// length, which depends on the corner). nullopt when there is none.
std::optional<Corner> startCorner(const Pose2D& start, Point next, const TurnShape& shape) {
  const Point from{start.x, start.y};
  double d = 0.0;
  for (int i = 0; i < 60; ++i) {
    const Point c{from.x + d * std::cos(start.theta), from.y + d * std::sin(start.theta)};
    if (distance(c, next) < 1e-9) return std::nullopt;
    const double deflection = normalizeAngle(headingOf(c, next) - start.theta);
    if (std::abs(deflection) > kFoldBack) return std::nullopt;
    const double tangent = turnTangentLength(deflection, shape);
    if (std::abs(tangent - d) < 1e-10) return Corner{c, deflection, tangent, shape.sharpness, true};
    d = tangent;
  }
  return std::nullopt;
}

// Appends a straight from the chain's end along its heading up to the foot of `to`, if ahead.
void appendStraightTo(TrajectoryChain& chain, const Pose2D& start, Point to) {
  const Pose2D from = chain.empty() ? start : chain.end();
  const double length = (to.x - from.x) * std::cos(from.theta) + (to.y - from.y) * std::sin(from.theta);
  if (length > 1e-9) chain.append({from, length, 0.0, 0.0});
}

}  // namespace

void validate(const TurnShape& shape) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!(positive(shape.maxCurvature) && positive(shape.sharpness) && positive(shape.maxSharpness) &&
        shape.sharpness <= shape.maxSharpness)) {
    throw InvalidArgumentError(
        "turn shape: curvature and sharpnesses must be positive and finite, sharpness <= maxSharpness");
  }
}

std::vector<TrajectorySegment> symmetricTurn(const Pose2D& start, double deflection, const TurnShape& shape) {
  if (std::abs(deflection) < kNoTurn) return {};
  const TurnParts parts = turnParts(deflection, shape);
  const double sign = deflection > 0.0 ? 1.0 : -1.0;
  std::vector<TrajectorySegment> turn;
  turn.push_back({start, parts.clothoid, 0.0, sign * shape.sharpness});
  if (parts.arc > 1e-12) turn.push_back({turn.back().end(), parts.arc, sign * parts.peak, 0.0});
  turn.push_back({turn.back().end(), parts.clothoid, sign * parts.peak, -sign * shape.sharpness});
  return turn;
}

double turnTangentLength(double deflection, const TurnShape& shape) {
  const double a = std::abs(deflection);
  if (a < kNoTurn) return 0.0;
  if (a >= M_PI) return std::numeric_limits<double>::infinity();
  // The middle of the turn (its half: clothoid and half the arc, turning left) lies on the
  // bisector of the corner: T = x + y tan(a / 2).
  const TurnParts parts = turnParts(a, shape);
  Pose2D middle = TrajectorySegment{{}, parts.clothoid, 0.0, shape.sharpness}.end();
  if (parts.arc > 0.0) middle = TrajectorySegment{middle, 0.5 * parts.arc, parts.peak, 0.0}.end();
  return middle.x + middle.y * std::tan(0.5 * a);
}

std::optional<std::vector<TrajectorySegment>> cornerTurn(const Pose2D& before, const Pose2D& corner,
                                                         const Pose2D& after, const TurnShape& shape) {
  validate(shape);
  const Point b{before.x, before.y}, c{corner.x, corner.y}, a{after.x, after.y};
  if (distance(b, c) < 1e-9 || distance(c, a) < 1e-9) return std::nullopt;
  const double in = headingOf(b, c);
  const double deflection = normalizeAngle(headingOf(c, a) - in);
  if (std::abs(deflection) > kFoldBack) return std::nullopt;
  const double t = turnTangentLength(deflection, shape);
  return symmetricTurn({c.x - t * std::cos(in), c.y - t * std::sin(in), in}, deflection, shape);
}

std::optional<TrajectorySegment> clothoidJoin(const Pose2D& from, const Pose2D& to, double maxCurvature) {
  const double dx = to.x - from.x, dy = to.y - from.y, r = std::hypot(dx, dy);
  if (r < 1e-3) return std::nullopt;
  const double phi = std::atan2(dy, dx);
  const double phi0 = normalizeAngle(from.theta - phi), phi1 = normalizeAngle(to.theta - phi);
  const double delta = phi1 - phi0;
  // The phase over t in [0, 1] is A t^2 + (delta - A) t + phi0; Newton finds A with Y = 0
  // (the end lies on the chord), dY/dA = integral (t^2 - t) cos(phase).
  const auto integral = [&](double A, bool chord) {
    const auto phase = [&](double t) { return A * t * t + (delta - A) * t + phi0; };
    return gauss_legendre::integrate(0.0, 1.0, gauss_legendre::piecesFor(1.0, delta - A, 2.0 * A), [&](double t) {
      const double p = phase(t);
      return chord ? PlanarVector{std::cos(p), std::sin(p)} : PlanarVector{std::sin(p), (t * t - t) * std::cos(p)};
    });
  };
  // Bertolazzi & Frego's initial guess.
  const double p0 = phi0 / M_PI, p1 = phi1 / M_PI;
  double A = (phi0 + phi1) * (3.070645 + 0.947923 * p0 * p1 - 0.673029 * (p0 * p0 + p1 * p1));
  PlanarVector g = integral(A, false);
  for (int i = 0; i < 30 && std::abs(g.x) > 1e-13; ++i) {
    if (g.y == 0.0) return std::nullopt;
    A -= g.x / g.y;
    g = integral(A, false);
  }
  const PlanarVector xy = integral(A, true);
  if (!(std::abs(g.x) <= 1e-10 && xy.x > 0.0)) return std::nullopt;
  const double length = r / xy.x;
  const TrajectorySegment segment{from, length, (delta - A) / length, 2.0 * A / (length * length)};
  if (std::max(std::abs(segment.curvature), std::abs(segment.curvatureAt(length))) > maxCurvature) return std::nullopt;
  return segment;
}

std::optional<TrajectoryChain> smoothPolyline(const Pose2D& start, const std::vector<Pose2D>& targets,
                                              const TurnShape& shape) {
  validate(shape);
  std::vector<Point> points{{start.x, start.y}};
  for (const Pose2D& t : targets) {
    if (distance(points.back(), {t.x, t.y}) > 1e-6) points.push_back({t.x, t.y});
  }
  if (points.size() < 2) return std::nullopt;
  // The corners: maybe one ahead of the start for its heading, then the polyline's own.
  std::vector<Corner> corners;
  std::vector<Point> line{points.front()};
  if (std::abs(normalizeAngle(headingOf(points[0], points[1]) - start.theta)) > kNoTurn) {
    const std::optional<Corner> first = startCorner(start, points[1], shape);
    if (!first) return std::nullopt;
    corners.push_back(*first);
    line.push_back(first->at);
  }
  line.insert(line.end(), points.begin() + 1, points.end());
  for (std::size_t i = corners.size() + 1; i + 1 < line.size(); ++i) {
    const double deflection = normalizeAngle(headingOf(line[i], line[i + 1]) - headingOf(line[i - 1], line[i]));
    if (std::abs(deflection) > kFoldBack) return std::nullopt;
    corners.push_back({line[i], deflection, turnTangentLength(deflection, shape), shape.sharpness, false});
  }
  // corners[k] sits at line[k + 1]; the leg line[j] -> line[j + 1] holds the end of the turn at
  // line[j] and the start of the one at line[j + 1]. Turns that overlap share the leg in
  // proportion to their sizes (a fixed turn keeps its size) and grow sharper to fit their share.
  const auto tangentAt = [&](std::size_t vertex) {
    return vertex == 0 || vertex + 1 == line.size() ? 0.0 : corners[vertex - 1].tangent;
  };
  std::vector<double> allowed(corners.size(), std::numeric_limits<double>::infinity());
  for (std::size_t j = 0; j + 1 < line.size(); ++j) {
    const double length = distance(line[j], line[j + 1]);
    const double a = tangentAt(j), b = tangentAt(j + 1);
    if (a + b <= length + 1e-9) continue;
    const bool aFixed = j > 0 && corners[j - 1].fixed;
    if (aFixed && a > length) return std::nullopt;
    const double shareA = aFixed ? a : length * a / (a + b);
    if (j > 0) allowed[j - 1] = std::min(allowed[j - 1], shareA);
    if (j + 2 < line.size()) allowed[j] = std::min(allowed[j], length - shareA);
  }
  for (std::size_t k = 0; k < corners.size(); ++k) {
    if (corners[k].tangent <= allowed[k] + 1e-9) continue;
    if (corners[k].fixed) return std::nullopt;
    const std::optional<double> sharpness = sharpnessFitting(corners[k].deflection, shape, allowed[k]);
    if (!sharpness) return std::nullopt;
    corners[k].sharpness = *sharpness;
  }
  TrajectoryChain chain;
  for (const Corner& corner : corners) {
    if (std::abs(corner.deflection) < kNoTurn) continue;  // straight on through a target
    TurnShape turnShape = shape;
    turnShape.sharpness = corner.sharpness;
    const double tangent = turnTangentLength(corner.deflection, turnShape);
    const double in = chain.empty() ? start.theta : chain.end().theta;
    appendStraightTo(chain, start, {corner.at.x - tangent * std::cos(in), corner.at.y - tangent * std::sin(in)});
    const Pose2D from = chain.empty() ? start : chain.end();
    for (const TrajectorySegment& segment : symmetricTurn(from, corner.deflection, turnShape)) chain.append(segment);
  }
  appendStraightTo(chain, start, line.back());
  if (chain.empty()) return std::nullopt;
  return chain;
}

}  // namespace rgnav
