// Split-and-merge of a point run; see SplitAndMerge.h.
#include "core/lines/SplitAndMerge.h"

#include <cmath>
#include <optional>

#include "core/lines/PointMoments.h"

namespace rgnav {
namespace {

using Range = std::pair<std::size_t, std::size_t>;

// Index of the point of [first, last) farthest from the chord first -> last-1, and its distance.
std::pair<std::size_t, double> farthestFromChord(std::span<const Eigen::Vector2d> points, const Range& r) {
  const Eigen::Vector2d a = points[r.first], b = points[r.second - 1];
  const Eigen::Vector2d d = b - a;
  const double len = d.norm();
  std::pair<std::size_t, double> best{r.first, 0.0};
  for (std::size_t i = r.first + 1; i + 1 < r.second; ++i) {
    const Eigen::Vector2d v = points[i] - a;
    const double dist = len > 0.0 ? std::fabs(d.x() * v.y() - d.y() * v.x()) / len : v.norm();
    if (dist > best.second) best = {i, dist};
  }
  return best;
}

void split(std::span<const Eigen::Vector2d> points, const Range& r, double threshold, std::vector<Range>& out) {
  const auto [at, dist] = farthestFromChord(points, r);
  if (dist <= threshold) {
    out.push_back(r);
    return;
  }
  // The farthest point is the corner: it starts the second piece.
  split(points, {r.first, at}, threshold, out);
  split(points, {at, r.second}, threshold, out);
}

// The TLS line of the points of r, if they define one.
std::optional<LineFit> fitRange(std::span<const Eigen::Vector2d> points, const Range& r) {
  PointMoments moments;
  for (std::size_t i = r.first; i < r.second; ++i) moments.add(points[i]);
  if (moments.count() < 2.0 || !(moments.scatter().trace() > 0.0)) return std::nullopt;
  return moments.fitLine();
}

double distance(const LineFit& fit, const Eigen::Vector2d& p) { return std::fabs(fit.normal.dot(p) - fit.distanceM); }

// Largest orthogonal distance of the points of r from their TLS line.
double maxResidual(std::span<const Eigen::Vector2d> points, const Range& r) {
  const auto fit = fitRange(points, r);
  if (!fit) return 0.0;
  double worst = 0.0;
  for (std::size_t i = r.first; i < r.second; ++i) worst = std::max(worst, distance(*fit, points[i]));
  return worst;
}

// The split point is the one farthest from a chord, which near a corner may be a point or two
// off: a point at the border of two pieces moves to the piece whose line is nearer.
void adjustBoundary(std::span<const Eigen::Vector2d> points, Range& left, Range& right) {
  const auto a = fitRange(points, left), b = fitRange(points, right);
  if (!a || !b) return;
  while (left.second - left.first > 2 && distance(*b, points[left.second - 1]) < distance(*a, points[left.second - 1]))
    right.first = --left.second;
  while (right.second - right.first > 2 && distance(*a, points[right.first]) < distance(*b, points[right.first]))
    left.second = ++right.first;
}

}  // namespace

std::vector<std::pair<std::size_t, std::size_t>> splitAndMerge(std::span<const Eigen::Vector2d> points,
                                                               double splitDistanceM) {
  std::vector<Range> pieces;
  if (points.empty()) return pieces;
  split(points, {0, points.size()}, splitDistanceM, pieces);
  std::vector<Range> merged;
  for (const Range& piece : pieces) {
    if (!merged.empty() && maxResidual(points, {merged.back().first, piece.second}) <= splitDistanceM)
      merged.back().second = piece.second;
    else
      merged.push_back(piece);
  }
  for (std::size_t i = 1; i < merged.size(); ++i) adjustBoundary(points, merged[i - 1], merged[i]);
  return merged;
}

}  // namespace rgnav
