// StructureLines: the long line segments of the region line maps (walls, large furniture
// faces) and a fast test whether a point lies on one of them or on its straight continuation
// for a while: a wall is often seen in pieces (a chair in front of it hides a stretch), and the
// short pieces line up with the long ones. Points on structure lines are not small objects; a
// point cluster touching one is part of a wall, not a table leg.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/lines/LineSegment.h"

namespace rgnav {

class StructureLines {
 public:
  // `maxDistanceM`: how far from a line a point still lies on it; `extensionM`: how far the
  // line continues beyond each end.
  StructureLines(double maxDistanceM, double extensionM);

  void add(const LineSegment& line);
  bool onLine(const Eigen::Vector2d& p) const;

 private:
  std::uint64_t key(std::int64_t cx, std::int64_t cy) const;

  double maxDistance_;
  double extension_;
  double bucket_;
  std::vector<LineSegment> lines_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> buckets_;  // hash grid cell -> lines
};

}  // namespace rgnav
