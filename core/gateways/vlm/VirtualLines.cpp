// Grouping of line segments into virtual lines; see VirtualLines.h.
#include "core/gateways/vlm/VirtualLines.h"

#include <algorithm>
#include <limits>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

struct Group {
  PointMoments moments;
  PlanarLine line;
  double supportM = 0.0;
  std::size_t segmentCount = 0;

  void add(const LineSegment& s) {
    moments.add(s.moments);
    const LineFit fit = moments.fitLine();
    line = {fit.centroid, fit.direction};
    supportM += s.length();
    ++segmentCount;
  }
};

// Mean endpoint offset of s from the group's line if s lies on it within the limits.
std::optional<double> fitOffset(const Group& g, const LineSegment& s, const VirtualLineParams& p) {
  const PlanarLine own{s.start, s.direction()};
  if (angleBetween(own, g.line) > p.maxAngleRad) return std::nullopt;
  const double a = std::fabs(g.line.signedOffset(s.start)), b = std::fabs(g.line.signedOffset(s.end));
  if (a > p.maxOffsetM || b > p.maxOffsetM) return std::nullopt;
  return 0.5 * (a + b);
}

}  // namespace

std::vector<VirtualLine> groupVirtualLines(std::vector<LineSegment> segments, const VirtualLineParams& params) {
  if (!(params.maxAngleRad >= 0.0 && params.maxAngleRad < M_PI / 2) || !(params.maxOffsetM >= 0.0) ||
      !(params.minSupportM >= 0.0))
    throw InvalidArgumentError("virtual lines: need 0 <= angle < 90 degrees and non-negative offset and support");
  std::sort(segments.begin(), segments.end(),
            [](const LineSegment& a, const LineSegment& b) { return a.length() > b.length(); });
  std::vector<Group> groups;
  for (const LineSegment& s : segments) {
    if (s.length() <= 0.0) continue;
    Group* best = nullptr;
    double bestOffset = std::numeric_limits<double>::infinity();
    for (Group& g : groups) {
      if (const auto offset = fitOffset(g, s, params); offset && *offset < bestOffset) {
        bestOffset = *offset;
        best = &g;
      }
    }
    if (!best) best = &groups.emplace_back();
    best->add(s);
  }
  std::vector<VirtualLine> lines;
  for (const Group& g : groups)
    if (g.supportM >= params.minSupportM) lines.push_back({g.line, g.supportM, g.segmentCount});
  return lines;
}

}  // namespace rgnav
