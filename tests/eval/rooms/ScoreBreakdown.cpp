// Where the room scores lose; see ScoreBreakdown.h.
#include "tests/eval/rooms/ScoreBreakdown.h"

#include <map>
#include <vector>

#include "core/common/Errors.h"

namespace rgnav {

ScoreBreakdown breakDownScore(const GroundTruth& truth, const OccupancyGrid& world,
                              std::span<const SegmentPixels> segments, const RoomScore& score,
                              std::span<const int> unreachableRooms) {
  const auto rooms = std::size_t(truth.roomCount);
  // Per pixel: claimed at all, and claimed by a segment whose best room is the pixel's room.
  std::vector<std::uint8_t> claimed(truth.labels.size(), 0), claimedByOwner(truth.labels.size(), 0);
  std::map<std::uint64_t, int> bestRoom;
  for (const SegmentMatch& s : score.segments) bestRoom[s.id] = s.room;
  for (const SegmentPixels& segment : segments) {
    const auto best = bestRoom.find(segment.id);
    for (const std::size_t pixel : segment.pixels) {
      claimed[pixel] = 1;
      if (best != bestRoom.end() && truth.labels[pixel] >= 0 && truth.labels[pixel] == best->second)
        claimedByOwner[pixel] = 1;
    }
  }

  std::vector<double> pixels(rooms, 0.0), reachable(rooms, 0.0), covered(rooms, 0.0);
  for (std::size_t i = 0; i < truth.labels.size(); ++i) {
    if (truth.labels[i] < 0) continue;
    const auto room = std::size_t(truth.labels[i]);
    ++pixels[room];
    reachable[room] += world.cells()[i] == Cell::Free;
    covered[room] += claimed[i];
  }
  for (const int room : unreachableRooms) reachable[std::size_t(room)] = 0.0;
  ScoreBreakdown out;
  for (std::size_t r = 0; r < rooms; ++r) {
    out.ceilingMean += reachable[r] / pixels[r] / double(rooms);
    out.coveredMean += covered[r] / pixels[r] / double(rooms);
  }

  double total = 0.0;
  for (const SegmentPixels& segment : segments) {
    const auto best = bestRoom.find(segment.id);
    if (best == bestRoom.end()) continue;  // dropped by the scoring
    total += double(segment.pixels.size());
    for (const std::size_t pixel : segment.pixels) {
      const int label = truth.labels[pixel];
      if (label == best->second) continue;
      if (label < 0)
        ++out.offRoomShare;
      else if (claimedByOwner[pixel])
        ++out.leakedShare;
      else
        ++out.mergedShare;
    }
  }
  if (total > 0.0) {
    out.offRoomShare /= total;
    out.leakedShare /= total;
    out.mergedShare /= total;
  }
  return out;
}

double furnitureShareMean(const GroundTruth& truth, const FurnitureTruth& furniture) {
  if (furniture.blobOfCell.size() != truth.labels.size())
    throw InvalidArgumentError("furnitureShareMean: the furniture and the ground truth differ in size");
  const auto rooms = std::size_t(truth.roomCount);
  std::vector<double> pixels(rooms, 0.0), covered(rooms, 0.0);
  for (std::size_t i = 0; i < truth.labels.size(); ++i) {
    if (truth.labels[i] < 0) continue;
    const auto room = std::size_t(truth.labels[i]);
    ++pixels[room];
    covered[room] += furniture.blobOfCell[i] >= 0;
  }
  double mean = 0.0;
  for (std::size_t r = 0; r < rooms; ++r) mean += covered[r] / pixels[r] / double(rooms);
  return mean;
}

}  // namespace rgnav
