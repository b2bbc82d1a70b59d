// Synthetic line maps; see SyntheticLines.h.
#include "core/objects/testing/SyntheticLines.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace rgnav::testing {

std::vector<LineSegment> syntheticLineMap(std::size_t count, unsigned seed) {
  std::mt19937 random(seed);
  const auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
  const auto direction = [](double a) { return Eigen::Vector2d(std::cos(a), std::sin(a)); };
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> ends;
  const std::size_t boxSides = 4 * ((count * 4 / 10) / 4);
  while (ends.size() < boxSides) {
    const Eigen::Vector2d c(uniform(-10, 10), uniform(-10, 10));
    const double heading = uniform(0, M_PI), half[2] = {uniform(0.2, 1.0), uniform(0.2, 1.0)};
    for (int side = 0; side < 4; ++side) {
      const double a = heading + side * M_PI / 2;
      const Eigen::Vector2d along = direction(a + M_PI / 2);
      const Eigen::Vector2d mid = c + half[side % 2] * direction(a);
      const double h = half[(side + 1) % 2];
      const Eigen::Vector2d p = mid - (h - uniform(0, 0.08)) * along, q = mid + (h - uniform(0, 0.08)) * along;
      // Turn the side about its middle by a small angle.
      const double turn = uniform(-1.5, 1.5) * M_PI / 180;
      const Eigen::Vector2d m = 0.5 * (p + q), half_pq = 0.5 * (q - p);
      const Eigen::Vector2d r(std::cos(turn) * half_pq.x() - std::sin(turn) * half_pq.y(),
                              std::sin(turn) * half_pq.x() + std::cos(turn) * half_pq.y());
      ends.emplace_back(m - r, m + r);
    }
  }
  while (ends.size() < count) {
    const Eigen::Vector2d p(uniform(-10, 10), uniform(-10, 10));
    ends.emplace_back(p, p + uniform(0.2, 3.0) * direction(uniform(0, M_PI)));
  }
  std::shuffle(ends.begin(), ends.end(), random);
  std::vector<LineSegment> lines;
  for (std::size_t i = 0; i < count; ++i) lines.push_back(segmentFromEndpoints(i + 1, ends[i].first, ends[i].second));
  return lines;
}

}  // namespace rgnav::testing
