// FramedQuadtreeLandmarks: farthest-first landmarks and their Dijkstra distances (see the header).
#include "core/nav/planning/FramedQuadtreeLandmarks.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>


namespace rgnav {

namespace {

// Any-angle distances from `source` to every node (kUnreachable where none).
std::vector<double> distancesFrom(const FramedQuadtree& tree, const LineOfSight& lineOfSight, std::int32_t source) {
  std::vector<double> distance(tree.nodeCount(), FramedQuadtreeLandmarks::kUnreachable);
  std::vector<std::int32_t> parent(tree.nodeCount(), -1);
  std::vector<char> closed(tree.nodeCount(), 0);
  std::vector<std::pair<double, std::int32_t>> heap{{0.0, source}};
  const auto later = [](const auto& a, const auto& b) { return a.first > b.first; };
  distance[static_cast<std::size_t>(source)] = 0.0;
  const auto centre = [&](std::int32_t n) {
    const CellIndex c = tree.nodeCell(n);
    return Eigen::Vector2d(c.col + 0.5, c.row + 0.5);
  };
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), later);
    const auto [d, node] = heap.back();
    heap.pop_back();
    const auto i = static_cast<std::size_t>(node);
    if (closed[i] || d != distance[i]) continue;
    const Eigen::Vector2d x = centre(node);
    if (parent[i] >= 0 && !lineOfSight.free(centre(parent[i]), x)) {
      distance[i] = FramedQuadtreeLandmarks::kUnreachable;
      tree.forEachNeighbour(node, [&](std::int32_t n) {
        if (!closed[static_cast<std::size_t>(n)]) return;
        const double through = distance[static_cast<std::size_t>(n)] + (centre(n) - x).norm();
        if (through < distance[i]) {
          distance[i] = through;
          parent[i] = n;
        }
      });
      heap.emplace_back(distance[i], node);
      std::push_heap(heap.begin(), heap.end(), later);
      continue;
    }
    closed[i] = 1;
    const std::int32_t from = parent[i] >= 0 ? parent[i] : node;
    const Eigen::Vector2d f = centre(from);
    tree.forEachNeighbour(node, [&](std::int32_t n) {
      const auto k = static_cast<std::size_t>(n);
      if (closed[k]) return;
      const double through = distance[static_cast<std::size_t>(from)] + (centre(n) - f).norm();
      if (through < distance[k]) {
        distance[k] = through;
        parent[k] = from;
        heap.emplace_back(through, n);
        std::push_heap(heap.begin(), heap.end(), later);
      }
    });
  }
  // Theta*'s expansions are not ordered by distance, so a node expanded early may keep a distance
  // above a neighbour's plus the edge between them; relaxing along the graph edges until no
  // distance drops makes every edge consistent.
  for (std::size_t n = 0; n < distance.size(); ++n)
    if (distance[n] != FramedQuadtreeLandmarks::kUnreachable) heap.emplace_back(distance[n], static_cast<std::int32_t>(n));
  std::make_heap(heap.begin(), heap.end(), later);
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), later);
    const double d = heap.back().first;
    const std::int32_t node = heap.back().second;
    heap.pop_back();
    if (d != distance[static_cast<std::size_t>(node)]) continue;
    const Eigen::Vector2d x = centre(node);
    tree.forEachNeighbour(node, [&](std::int32_t n) {
      const double through = d + (centre(n) - x).norm();
      if (through < distance[static_cast<std::size_t>(n)]) {
        distance[static_cast<std::size_t>(n)] = through;
        heap.emplace_back(through, n);
        std::push_heap(heap.begin(), heap.end(), later);
      }
    });
  }
  return distance;
}

// A node of the largest connected component of the graph.
std::int32_t largestComponentNode(const FramedQuadtree& tree) {
  std::vector<char> seen(tree.nodeCount(), 0);
  std::vector<std::int32_t> pending;
  std::int32_t best = 0;
  std::size_t bestSize = 0;
  for (std::size_t root = 0; root < tree.nodeCount(); ++root) {
    if (seen[root]) continue;
    seen[root] = 1;
    pending.assign(1, static_cast<std::int32_t>(root));
    std::size_t size = 0;
    while (!pending.empty()) {
      const std::int32_t node = pending.back();
      pending.pop_back();
      ++size;
      tree.forEachNeighbour(node, [&](std::int32_t n) {
        if (!seen[static_cast<std::size_t>(n)]) {
          seen[static_cast<std::size_t>(n)] = 1;
          pending.push_back(n);
        }
      });
    }
    if (size > bestSize) {
      bestSize = size;
      best = static_cast<std::int32_t>(root);
    }
  }
  return best;
}

// The node with the largest finite value.
std::int32_t farthest(const std::vector<double>& values) {
  std::int32_t best = 0;
  for (std::size_t n = 0; n < values.size(); ++n)
    if (values[n] != FramedQuadtreeLandmarks::kUnreachable && values[n] > values[static_cast<std::size_t>(best)])
      best = static_cast<std::int32_t>(n);
  return best;
}

}  // namespace

FramedQuadtreeLandmarks::FramedQuadtreeLandmarks(const FramedQuadtree& tree, const LineOfSight& lineOfSight) {
  const std::size_t nodes = tree.nodeCount();
  distances_.assign(nodes * kCount, kUnreachable);
  if (nodes == 0) return;
  std::vector<double> nearest = distancesFrom(tree, lineOfSight, largestComponentNode(tree));  // to the landmarks so far
  for (std::size_t l = 0; l < kCount; ++l) {
    const std::vector<double> d = distancesFrom(tree, lineOfSight, farthest(nearest));
    for (std::size_t n = 0; n < nodes; ++n) {
      distances_[n * kCount + l] = d[n];
      nearest[n] = l == 0 ? d[n] : std::min(nearest[n], d[n]);
    }
  }
}

}  // namespace rgnav
