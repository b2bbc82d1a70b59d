// TangentVisibility: the convex obstacle corners of an OccupancyGrid and, for a point, the corners
// it sees along a line tangent to the obstacle at the corner: the candidate edges of the tangent
// (sparse) visibility graph (Oh & Leong, "Edge N-Level Sparse Visibility Graphs", SoCS 2017) that
// VisibilityGraph searches. A convex corner is a grid vertex where exactly one of the four cells
// around is blocked; the line through it is tangent unless it runs into the blocked cell's
// quadrant or the opposite one.
// The seen region is scanned row by row as intervals of a horizontal grid line that rays from the
// point reach through runs of free cells (the line-of-sight scan of the paper and of Anya, Harabor
// et al., JAIR 2016). Unlike them the scan is deliberately loose (floating-point bounds widened,
// squeezes and grid-line rules ignored): it only proposes corners, and each proposal is accepted
// only if segmentFree (SegmentVisibility.h) holds, so the edges follow the shared collision model
// exactly.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

class TangentVisibility {
 public:
  // The grid must outlive this object and not change.
  explicit TangentVisibility(const OccupancyGrid& grid);

  int cornerCount() const { return static_cast<int>(vertices_.size()); }
  // The grid vertex of corner `id`, and the diagonal direction (each coordinate +-1) from it into
  // its blocked cell.
  const Eigen::Vector2i& vertex(int id) const { return vertices_[static_cast<std::size_t>(id)]; }
  const Eigen::Vector2i& wrap(int id) const { return wraps_[static_cast<std::size_t>(id)]; }

  // Whether direction `d` from or to corner `id` lies on a line tangent to its obstacle.
  bool tangentAt(int id, const Eigen::Vector2d& d) const;

  // Replaces `out` with the corners w other than `from` such that the segment p-w is free and its
  // line is tangent at w, and at `from` if `from` is a corner id (then p must be its vertex; -1
  // for any other point). Not thread-safe (a scratch stamp array is reused).
  void seenTangentCorners(const Eigen::Vector2d& p, int from, std::vector<int>& out) const;

 private:
  struct Interval {
    int line;  // the horizontal grid line y = line
    double lo, hi;
  };
  bool blocked(int col, int row) const;
  // Scans the grid lines above (step +1) or below (step -1) p, starting from x in [lo, hi].
  void scanRows(const Eigen::Vector2d& p, int step, double lo, double hi) const;
  // Walks the grid line y = p.y() (an integer) from p in direction step (+1 right, -1 left).
  void walkLine(const Eigen::Vector2d& p, int step) const;
  void propose(int line, double lo, double hi) const;
  void proposeId(int id) const;

  const OccupancyGrid& grid_;
  int width_, height_;
  std::vector<Eigen::Vector2i> vertices_, wraps_;
  std::vector<int> idAt_;                               // (width+1)*(height+1) vertices, -1: no corner
  std::vector<std::vector<int>> lineCorners_;           // per horizontal grid line, ids sorted by x
  std::vector<std::vector<std::pair<int, int>>> runs_;  // per row, runs of free cells [first, last]
  mutable std::vector<std::uint32_t> stamp_;
  mutable std::uint32_t currentStamp_ = 0;
  mutable std::vector<int> proposed_;
  mutable std::vector<Interval> stack_;
};

}  // namespace rgnav
