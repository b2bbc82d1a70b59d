// The room segmentation benchmark's metric; see RoomScoring.h.
#include "tests/eval/rooms/RoomScoring.h"

#include <numeric>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

template <typename T, typename F>
double meanOf(const std::vector<T>& items, F ratio) {
  if (items.empty()) return 0.0;
  double sum = 0.0;
  for (const T& item : items) sum += ratio(item);
  return sum / double(items.size());
}

template <typename T, typename F>
std::size_t sumOf(const std::vector<T>& items, F value) {
  return std::accumulate(items.begin(), items.end(), std::size_t{0},
                         [&](std::size_t sum, const T& item) { return sum + value(item); });
}

}  // namespace

double RoomScore::recallMean() const { return meanOf(rooms, [](const RoomMatch& r) { return r.recall(); }); }
double RoomScore::precisionMean() const {
  return meanOf(segments, [](const SegmentMatch& s) { return s.precision(); });
}
std::size_t RoomScore::roomOverlapSum() const { return sumOf(rooms, [](const RoomMatch& r) { return r.overlap; }); }
std::size_t RoomScore::roomPixelSum() const { return sumOf(rooms, [](const RoomMatch& r) { return r.pixels; }); }
std::size_t RoomScore::segmentOverlapSum() const {
  return sumOf(segments, [](const SegmentMatch& s) { return s.overlap; });
}
std::size_t RoomScore::segmentPixelSum() const {
  return sumOf(segments, [](const SegmentMatch& s) { return s.pixels; });
}

RoomScore scoreRooms(const GroundTruth& truth, std::span<const SegmentPixels> segments) {
  RoomScore score;
  const auto roomCount = static_cast<std::size_t>(truth.roomCount);
  score.rooms.resize(roomCount);
  for (std::size_t r = 0; r < roomCount; ++r) score.rooms[r].room = int(r);
  for (const int label : truth.labels)
    if (label >= 0) ++score.rooms[std::size_t(label)].pixels;

  for (const SegmentPixels& segment : segments) {
    if (segment.pixels.size() < kMinSegmentPixels) {
      ++score.droppedSegments;
      continue;
    }
    SegmentMatch match{segment.id, segment.pixels.size(), 0, -1, std::vector<std::size_t>(roomCount, 0)};
    for (const std::size_t pixel : segment.pixels) {
      if (pixel >= truth.labels.size())
        throw InvalidArgumentError("room scoring: pixel " + std::to_string(pixel) + " of segment " +
                                   std::to_string(segment.id) + " lies outside the ground truth");
      if (const int label = truth.labels[pixel]; label >= 0) ++match.roomOverlaps[std::size_t(label)];
    }
    for (std::size_t r = 0; r < roomCount; ++r)
      if (match.roomOverlaps[r] > match.overlap) {
        match.overlap = match.roomOverlaps[r];
        match.room = int(r);
      }
    score.segments.push_back(std::move(match));
  }

  for (std::size_t s = 0; s < score.segments.size(); ++s)
    for (std::size_t r = 0; r < roomCount; ++r)
      if (score.segments[s].roomOverlaps[r] > score.rooms[r].overlap) {
        score.rooms[r].overlap = score.segments[s].roomOverlaps[r];
        score.rooms[r].segment = s;
      }
  return score;
}

}  // namespace rgnav
