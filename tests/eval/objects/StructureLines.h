// StructureLines: the long line segments of the region line maps (walls, large furniture
// faces) and a fast test whether a point lies on one of them. Points on structure lines are not
// small objects; a point cluster touching one is part of a wall, not a table leg.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/lines/LineSegment.h"

namespace rgnav {

class StructureLines {
 public:
  // `maxDistanceM`: how far from a line (and beyond its ends) a point still lies on it.
  explicit StructureLines(double maxDistanceM);

  void add(const LineSegment& line);
  bool onLine(const Eigen::Vector2d& p) const;

 private:
  std::uint64_t key(std::int64_t cx, std::int64_t cy) const;

  double maxDistance_;
  double bucket_;
  std::vector<LineSegment> lines_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> buckets_;  // hash grid cell -> lines
};

}  // namespace rgnav
