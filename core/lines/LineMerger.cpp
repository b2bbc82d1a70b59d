// Line merging, thesis 3.1.1; see LineMerger.h.
#include "core/lines/LineMerger.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

// Distance of p from the infinite line through s.
double distanceToLine(const LineSegment& s, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = s.direction();
  const Eigen::Vector2d v = p - s.start;
  return std::fabs(d.x() * v.y() - d.y() * v.x());
}

}  // namespace

double lineDistance(const LineSegment& a, const LineSegment& b) {
  return 0.25 * (distanceToLine(b, a.start) + distanceToLine(b, a.end) + distanceToLine(a, b.start) +
                 distanceToLine(a, b.end));
}

double gapAlongLine(const LineSegment& a, const LineSegment& b) {
  const LineSegment& longer = a.length() >= b.length() ? a : b;
  const Eigen::Vector2d d = longer.direction();
  const auto interval = [&](const LineSegment& s) {
    const double u = d.dot(s.start), v = d.dot(s.end);
    return std::pair(std::min(u, v), std::max(u, v));
  };
  const auto [a0, a1] = interval(a);
  const auto [b0, b1] = interval(b);
  return std::max(b0 - a1, a0 - b1);
}

LineMerger::LineMerger(const LineMergerParams& params) : params_(params) {
  if (!(params.maxAngleRad >= 0.0 && params.maxAngleRad < M_PI / 2) || !(params.maxLineDistanceM >= 0.0) ||
      !(params.maxGapM >= 0.0))
    throw InvalidArgumentError("line merger: need 0 <= alpha_max < 90 degrees, D_L^max >= 0, D_gap^max >= 0");
}

std::optional<LineSegment> LineMerger::tryMerge(const LineSegment& a, const LineSegment& b) const {
  if (orientationDifference(a.orientationRad(), b.orientationRad()) > params_.maxAngleRad) return std::nullopt;
  if (lineDistance(a, b) > params_.maxLineDistanceM) return std::nullopt;
  if (gapAlongLine(a, b) > params_.maxGapM) return std::nullopt;

  LineSegment merged;
  merged.id = std::min(a.id, b.id);
  merged.moments = a.moments;
  merged.moments.add(b.moments);
  const LineFit fit = merged.moments.fitLine();
  const std::array<Eigen::Vector2d, 4> ends{a.start, a.end, b.start, b.end};
  double farthest = -1.0;
  for (std::size_t i = 0; i < ends.size(); ++i)
    for (std::size_t j = i + 1; j < ends.size(); ++j)
      if (const double d = (ends[i] - ends[j]).squaredNorm(); d > farthest) {
        farthest = d;
        merged.start = projectOntoLine(fit, ends[i]);
        merged.end = projectOntoLine(fit, ends[j]);
      }
  std::set_union(a.provenance.begin(), a.provenance.end(), b.provenance.begin(), b.provenance.end(),
                 std::back_inserter(merged.provenance));
  return merged;
}

std::size_t LineMerger::sweep(std::vector<LineSegment>& segments) const {
  const std::size_t n = segments.size();
  std::vector<double> key(n);
  for (std::size_t i = 0; i < n; ++i) key[i] = segments[i].orientationRad();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return key[x] < key[y]; });

  std::vector<bool> alive(n, true);
  std::size_t merges = 0;
  for (std::size_t pos = 0; pos < n; ++pos) {
    const std::size_t i = order[pos];
    if (!alive[i]) continue;
    // Upwards in the sorted array, wrapping at pi, while within the angle window of key[i].
    for (std::size_t step = 1; step < n; ++step) {
      const std::size_t j = order[(pos + step) % n];
      double ahead = key[j] - key[i];
      if (ahead < 0.0) ahead += M_PI;
      if (ahead > params_.maxAngleRad) break;
      if (!alive[j]) continue;
      if (auto merged = tryMerge(segments[i], segments[j])) {
        segments[i] = std::move(*merged);
        alive[j] = false;
        ++merges;
      }
    }
  }
  std::vector<LineSegment> kept;
  kept.reserve(n - merges);
  for (const std::size_t i : order)
    if (alive[i]) kept.push_back(std::move(segments[i]));
  segments = std::move(kept);
  return merges;
}

std::vector<LineSegment> LineMerger::merge(std::vector<LineSegment> segments) const {
  while (sweep(segments) > 0) {
  }
  return segments;
}

std::vector<LineSegment> unmerge(const LineSegment& merged, const std::vector<LineSegment>& originals) {
  std::unordered_map<SegmentId, const LineSegment*> byId;
  for (const auto& s : originals) byId.emplace(s.id, &s);
  std::vector<LineSegment> parts;
  for (const SegmentId id : merged.provenance) {
    const auto it = byId.find(id);
    if (it == byId.end()) throw NotAvailableError("unmerge: original segment " + std::to_string(id) + " not given");
    parts.push_back(*it->second);
  }
  return parts;
}

}  // namespace rgnav
