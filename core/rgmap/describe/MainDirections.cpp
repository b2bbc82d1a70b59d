// Dominant orientations of a line map; see MainDirections.h.
#include "core/rgmap/describe/MainDirections.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

void validate(const MainDirectionParams& p) {
  if (!(p.binWidthRad > 0.0 && p.binWidthRad <= p.windowRad && 2.0 * p.windowRad < p.minSeparationRad &&
        p.minSeparationRad <= M_PI / 2 && p.minSecondWeight >= 0.0 && p.minSecondWeight <= 1.0))
    throw InvalidArgumentError(
        "main directions: need 0 < binWidthRad <= windowRad < minSeparationRad / 2, minSeparationRad <= pi/2, "
        "minSecondWeight in [0, 1]");
}

// The length-weighted circular mean orientation of the lines within `window` of `center`.
MainDirection refine(std::span<const LineSegment> lines, double center, double window, double totalLength) {
  double c = 0.0, s = 0.0, length = 0.0;
  for (const LineSegment& l : lines) {
    const double a = l.orientationRad();
    if (orientationDifference(a, center) > window) continue;
    c += l.length() * std::cos(2.0 * a);
    s += l.length() * std::sin(2.0 * a);
    length += l.length();
  }
  double angle = 0.5 * std::atan2(s, c);
  if (angle < 0.0) angle += M_PI;
  return {angle >= M_PI ? 0.0 : angle, length, length / totalLength};
}

}  // namespace

std::vector<MainDirection> mainDirections(std::span<const LineSegment> lines, const MainDirectionParams& params) {
  validate(params);
  const int bins = std::max(1, int(std::lround(M_PI / params.binWidthRad)));
  const double width = M_PI / bins;
  std::vector<double> histogram(std::size_t(bins), 0.0);
  double total = 0.0;
  for (const LineSegment& l : lines) {
    histogram[std::size_t(std::min(bins - 1, int(l.orientationRad() / width)))] += l.length();
    total += l.length();
  }
  if (!(total > 0.0)) return {};

  // Triangular smoothing, circular over [0, pi): a single line peaks at its own bin.
  const int half = int(std::lround(params.windowRad / width));
  std::vector<double> smoothed(std::size_t(bins), 0.0);
  for (int b = 0; b < bins; ++b)
    for (int k = -half; k <= half; ++k)
      smoothed[std::size_t(b)] +=
          (1.0 - std::abs(k) / (half + 1.0)) * histogram[std::size_t(((b + k) % bins + bins) % bins)];
  const auto center = [width](int b) { return (b + 0.5) * width; };

  const int first = int(std::max_element(smoothed.begin(), smoothed.end()) - smoothed.begin());
  std::vector<MainDirection> out{refine(lines, center(first), params.windowRad, total)};
  int second = -1;
  for (int b = 0; b < bins; ++b)
    if (orientationDifference(center(b), out[0].angleRad) >= params.minSeparationRad &&
        (second < 0 || smoothed[std::size_t(b)] > smoothed[std::size_t(second)]))
      second = b;
  if (second < 0) return out;
  const MainDirection next = refine(lines, center(second), params.windowRad, total);
  if (next.lengthM > 0.0 && next.lengthM >= params.minSecondWeight * out[0].lengthM) out.push_back(next);
  return out;
}

}  // namespace rgnav
