// scoreRooms: the metric of the IPA room segmentation benchmark (Bormann et al., ICRA 2016,
// evaluation_segmentation.cpp; floorplans/SOURCES.md) for a set of segments against the
// ground-truth rooms of a floor plan:
//   - GT rooms: GroundTruth::labels (8-connected free components of X_gt_segmentation.png,
//     <= 100 px dropped);
//   - segments of <= 100 px are dropped, as the benchmark drops them;
//   - recall: per room, its largest overlap with one segment / the room's pixels;
//   - precision: per segment, its largest overlap with one room / the segment's pixels;
//   - each as the mean of the per-room (per-segment) ratios and as pooled pixel sums.
// Where it differs: the benchmark's segments partition the map (a label image); a segment here is
// any set of pixels (an RG Map region's freespace), and segments may overlap: each one is scored
// on its own, so a pixel two regions claim counts in both.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/sim/GroundTruth.h"

namespace rgnav {

inline constexpr std::size_t kMinSegmentPixels = 101;

struct SegmentPixels {
  std::uint64_t id = 0;              // the caller's name for it (e.g. a region ID)
  std::vector<std::size_t> pixels;   // indices row * width + col into the ground truth's grid, no repeats
};

inline constexpr std::size_t kNoMatch = static_cast<std::size_t>(-1);

struct RoomMatch {
  int room = -1;
  std::size_t pixels = 0;
  std::size_t overlap = 0;           // with its best segment
  std::size_t segment = kNoMatch;    // index into RoomScore::segments
  double recall() const { return pixels == 0 ? 0.0 : double(overlap) / double(pixels); }
};

struct SegmentMatch {
  std::uint64_t id = 0;
  std::size_t pixels = 0;
  std::size_t overlap = 0;  // with its best room
  int room = -1;            // its best room; -1 if it overlaps none
  std::vector<std::size_t> roomOverlaps;  // pixels in each room, by room ID
  double precision() const { return pixels == 0 ? 0.0 : double(overlap) / double(pixels); }
};

struct RoomScore {
  std::vector<RoomMatch> rooms;        // by room ID
  std::vector<SegmentMatch> segments;  // the scored segments (> 100 px), in input order
  std::size_t droppedSegments = 0;     // of <= 100 px

  double recallMean() const;
  double precisionMean() const;
  // Pixel sums: rooms' best overlaps / room pixels; segments' best overlaps / segment pixels.
  std::size_t roomOverlapSum() const;
  std::size_t roomPixelSum() const;
  std::size_t segmentOverlapSum() const;
  std::size_t segmentPixelSum() const;
};

// Throws InvalidArgumentError for a pixel index outside the ground truth's grid.
RoomScore scoreRooms(const GroundTruth& truth, std::span<const SegmentPixels> segments);

}  // namespace rgnav
