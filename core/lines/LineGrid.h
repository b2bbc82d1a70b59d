// LineGrid: the lines of a line map in a coarse uniform grid, so that the lines that may merge
// with a segment (thesis 3.1.1) are found without looking at all of them. This is what lets a
// region line map (5.2) take each new scan in time independent of the region's size; the
// thesis' angle-sorted window alone does not, since most lines of a hallway share two
// orientations.
// A line is registered in every cell that its capsule of radius reach/2 touches (cut into pieces
// no longer than a cell, each piece's bounding box grown by reach/2), and `near` reads the same
// cells of the query segment. So every stored line with a point within `reach` of a point of
// the segment is returned (the midpoint of such two points lies in a cell of both), plus some
// farther ones. If two segments merge under LineMergerParams p, each endpoint of the shorter one
// lies within 4 D_L^max of the longer one's line and their extents along it are at most
// D_gap^max apart, so they come within reach = D_gap^max + 4 D_L^max of each other (for a
// longer segment of nonzero length; extracted segments are at least minLengthM long).
// Not in the thesis.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/lines/LineMerger.h"
#include "core/lines/LineSegment.h"

namespace rgnav {

// How close two segments must come to be merged under `params` (see above).
double mergeReach(const LineMergerParams& params);

class LineGrid {
 public:
  using Handle = std::uint32_t;

  // Throws InvalidArgumentError unless cellM > 0 and reachM >= 0.
  LineGrid(double cellM, double reachM);

  // Stores `line`; the handle stays valid until the line is removed. Throws
  // InvalidArgumentError for non-finite endpoints.
  Handle insert(LineSegment line);
  // Takes the line out (`handle` must be of a stored line); the handle may be reused.
  LineSegment remove(Handle handle);
  const LineSegment& line(Handle handle) const { return slots_[handle].line; }
  // The line's orientationRad(), computed once on insert.
  double orientationRad(Handle handle) const { return slots_[handle].orientationRad; }
  std::size_t size() const { return size_; }

  // The stored lines that may come within reach of `segment` (see above), each once, by
  // ascending orientation, then ID: the order in which a sweep of LineMerger meets them.
  std::vector<Handle> near(const LineSegment& segment) const;

 private:
  // Keys of the cells the capsule of `segment` (radius reach/2) touches, sorted, unique.
  std::vector<std::uint64_t> cells(const LineSegment& segment) const;

  struct Slot {
    LineSegment line;
    double orientationRad = 0.0;
  };

  double cellM_;
  double halfReachM_;
  std::vector<Slot> slots_;
  std::vector<Handle> free_;
  std::size_t size_ = 0;
  std::unordered_map<std::uint64_t, std::vector<Handle>> grid_;
};

}  // namespace rgnav
