// Two-stage and naive quadrangle grouping, thesis 3.1; see QuadrangleGrouping.h.
#include "core/objects/QuadrangleGrouping.h"

#include <algorithm>
#include <array>

#include "core/common/Errors.h"
#include "core/objects/OverlapSuppression.h"

namespace rgnav {
namespace {

std::vector<Quadrangle> quadranglesOf(const std::vector<LineSegment>& lines, std::vector<SideCycle> cycles) {
  std::sort(cycles.begin(), cycles.end());
  cycles.erase(std::unique(cycles.begin(), cycles.end()), cycles.end());
  std::vector<Quadrangle> quadrangles;
  quadrangles.reserve(cycles.size());
  for (const SideCycle& cycle : cycles) quadrangles.push_back(makeQuadrangle(lines, cycle));
  return quadrangles;
}

}  // namespace

QuadrangleGrouping::QuadrangleGrouping(const GroupingParams& params) : params_(params) { validate(params); }

void QuadrangleGrouping::tryPairOfPairs(const std::vector<LineSegment>& lines, std::size_t i, std::size_t j,
                                        std::size_t k, std::size_t l, std::vector<SideCycle>& cycles) const {
  switch (classifyPairOfPairs(lines[i], lines[j], lines[k], lines[l], params_)) {
    case PairOfPairs::kQuadIJLK:
      cycles.push_back(canonicalCycle({i, j, l, k}));
      break;
    case PairOfPairs::kQuadIJKL:
      cycles.push_back(canonicalCycle({i, j, k, l}));
      break;
    default:
      break;
  }
}

std::vector<Quadrangle> QuadrangleGrouping::twoStage(const std::vector<LineSegment>& lines) const {
  std::vector<std::array<std::size_t, 2>> pairs;
  for (std::size_t i = 0; i < lines.size(); ++i)
    for (std::size_t j = i + 1; j < lines.size(); ++j)
      if (isNeighbourPair(lines[i], lines[j], params_)) pairs.push_back({i, j});
  std::vector<SideCycle> cycles;
  for (std::size_t p = 0; p < pairs.size(); ++p)
    for (std::size_t q = p + 1; q < pairs.size(); ++q) {
      const auto [i, j] = pairs[p];
      const auto [k, l] = pairs[q];
      if (i != k && i != l && j != k && j != l) tryPairOfPairs(lines, i, j, k, l, cycles);
    }
  return quadranglesOf(lines, std::move(cycles));
}

std::vector<Quadrangle> QuadrangleGrouping::naive(const std::vector<LineSegment>& lines) const {
  const std::size_t n = lines.size();
  const auto neighbours = [&](std::size_t x, std::size_t y) { return isNeighbourPair(lines[x], lines[y], params_); };
  std::vector<SideCycle> cycles;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      for (std::size_t c = b + 1; c < n; ++c)
        for (std::size_t d = c + 1; d < n; ++d) {
          if (neighbours(a, b) && neighbours(c, d)) tryPairOfPairs(lines, a, b, c, d, cycles);
          if (neighbours(a, c) && neighbours(b, d)) tryPairOfPairs(lines, a, c, b, d, cycles);
          if (neighbours(a, d) && neighbours(b, c)) tryPairOfPairs(lines, a, d, b, c, cycles);
        }
  return quadranglesOf(lines, std::move(cycles));
}

std::vector<Quadrangle> QuadrangleGrouping::group(const std::vector<LineSegment>& lines, double maxOverlapRatio) const {
  return removeContainedAndOverlapping(twoStage(lines), maxOverlapRatio);
}

std::vector<Quadrangle> removeContainedAndOverlapping(const std::vector<Quadrangle>& quadrangles,
                                                      double maxOverlapRatio) {
  if (!(maxOverlapRatio >= 0.0 && maxOverlapRatio < 1.0))
    throw InvalidArgumentError("quadrangle removal: maxOverlapRatio must lie in [0, 1)");
  std::vector<Polygon> outlines;
  std::vector<double> areas;
  for (const auto& q : quadrangles) {
    outlines.push_back(outline(q));
    areas.push_back(polygonArea(outlines.back()));
  }
  std::vector<Quadrangle> kept;
  for (const std::size_t i : suppressOverlaps(outlines, areas, OverlapMeasure::kShareOfOwnArea, maxOverlapRatio))
    kept.push_back(quadrangles[i]);
  return kept;
}

}  // namespace rgnav
