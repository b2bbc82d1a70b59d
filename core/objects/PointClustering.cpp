// Single-linkage clustering on a hash grid; see PointClustering.h.
#include "core/objects/PointClustering.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <unordered_map>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

struct DisjointSets {
  std::vector<std::size_t> parent;
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t find(std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

std::uint64_t cellKey(std::int64_t cx, std::int64_t cy) {
  return (std::uint64_t(cx) << 32) ^ (std::uint64_t(cy) & 0xffffffffULL);
}

}  // namespace

std::vector<std::vector<std::size_t>> clusterPoints(const std::vector<Eigen::Vector2d>& points, double maxGapM) {
  if (!(maxGapM > 0.0)) throw InvalidArgumentError("clusterPoints: maxGapM must be positive");
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> grid;
  const auto cell = [&](double c) { return std::int64_t(std::floor(c / maxGapM)); };
  for (std::size_t i = 0; i < points.size(); ++i) grid[cellKey(cell(points[i].x()), cell(points[i].y()))].push_back(i);

  DisjointSets sets(points.size());
  const double gap2 = maxGapM * maxGapM;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::int64_t cx = cell(points[i].x()), cy = cell(points[i].y());
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = grid.find(cellKey(cx + dx, cy + dy));
        if (it == grid.end()) continue;
        for (const std::size_t j : it->second)
          if (j > i && (points[i] - points[j]).squaredNorm() < gap2) sets.unite(i, j);
      }
  }
  std::map<std::size_t, std::vector<std::size_t>> byRoot;  // roots are the smallest index
  for (std::size_t i = 0; i < points.size(); ++i) byRoot[sets.find(i)].push_back(i);
  std::vector<std::vector<std::size_t>> clusters;
  for (auto& [root, members] : byRoot) clusters.push_back(std::move(members));
  return clusters;
}

}  // namespace rgnav
