// Tests the benchmark metric of RoomScoring.h on a hand-made ground truth: recall per room from
// its best segment, precision per segment from its best room, overlapping segments scored each on
// its own, segments of <= 100 px dropped, means and pooled pixel sums, rooms without a segment.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"
#include "tests/eval/rooms/RoomScoring.h"

using rgnav::SegmentPixels;

namespace {

constexpr int kWidth = 40, kHeight = 10;

// Room 0: columns 0..14 (150 px); column 15 a separator; room 1: columns 16..29 (140 px);
// room 2: columns 31..39 (90 px, kept although small: the rule is the ground truth's to apply).
rgnav::GroundTruth threeRooms() {
  rgnav::GroundTruth truth;
  truth.width = kWidth;
  truth.height = kHeight;
  truth.roomCount = 3;
  truth.labels.assign(kWidth * kHeight, -1);
  for (int row = 0; row < kHeight; ++row)
    for (int col = 0; col < kWidth; ++col)
      truth.labels[std::size_t(row * kWidth + col)] = col < 15 ? 0 : col >= 16 && col < 30 ? 1 : col >= 31 ? 2 : -1;
  return truth;
}

SegmentPixels columns(std::uint64_t id, int first, int last, int rows = kHeight) {
  SegmentPixels s{id, {}};
  for (int row = 0; row < rows; ++row)
    for (int col = first; col <= last; ++col) s.pixels.push_back(std::size_t(row * kWidth + col));
  return s;
}

SegmentPixels joined(std::uint64_t id, const SegmentPixels& a, const SegmentPixels& b) {
  SegmentPixels s{id, a.pixels};
  s.pixels.insert(s.pixels.end(), b.pixels.begin(), b.pixels.end());
  return s;
}

void assertNear(double expected, double actual) { CPPUNIT_ASSERT_DOUBLES_EQUAL(expected, actual, 1e-12); }

}  // namespace

class RoomScoringTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RoomScoringTest);
  CPPUNIT_TEST(scoresEachRoomAndSegmentByItsBestMatch);
  CPPUNIT_TEST(rejectsPixelsOutsideTheGroundTruth);
  CPPUNIT_TEST_SUITE_END();

 public:
  void scoresEachRoomAndSegmentByItsBestMatch() {
    const std::vector<SegmentPixels> segments{
        columns(1, 0, 14),                                        // room 0 exactly
        joined(2, columns(0, 15, 25), columns(0, 26, 29, 5)),     // separator + 120 px of room 1
        columns(3, 31, 35),                                       // 50 px: dropped
        joined(4, columns(0, 0, 9), columns(0, 16, 20))};         // overlaps 1 and 2
    const rgnav::RoomScore score = rgnav::scoreRooms(threeRooms(), segments);

    CPPUNIT_ASSERT_EQUAL(std::size_t(1), score.droppedSegments);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), score.segments.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(130), score.segments[1].pixels);
    CPPUNIT_ASSERT_EQUAL(1, score.segments[1].room);
    CPPUNIT_ASSERT_EQUAL(0, score.segments[2].room);
    assertNear(120.0 / 130.0, score.segments[1].precision());
    assertNear(100.0 / 150.0, score.segments[2].precision());

    CPPUNIT_ASSERT_EQUAL(std::size_t(0), score.rooms[0].segment);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), score.rooms[1].segment);
    CPPUNIT_ASSERT_EQUAL(rgnav::kNoMatch, score.rooms[2].segment);
    assertNear(120.0 / 140.0, score.rooms[1].recall());
    assertNear(0.0, score.rooms[2].recall());

    assertNear((1.0 + 120.0 / 140.0 + 0.0) / 3.0, score.recallMean());
    assertNear((1.0 + 120.0 / 130.0 + 100.0 / 150.0) / 3.0, score.precisionMean());
    CPPUNIT_ASSERT_EQUAL(std::size_t(270), score.roomOverlapSum());
    CPPUNIT_ASSERT_EQUAL(std::size_t(380), score.roomPixelSum());
    CPPUNIT_ASSERT_EQUAL(std::size_t(370), score.segmentOverlapSum());
    CPPUNIT_ASSERT_EQUAL(std::size_t(430), score.segmentPixelSum());
  }

  void rejectsPixelsOutsideTheGroundTruth() {
    SegmentPixels outside = columns(7, 0, 14);
    outside.pixels.push_back(kWidth * kHeight);
    CPPUNIT_ASSERT_THROW(rgnav::scoreRooms(threeRooms(), std::vector<SegmentPixels>{outside}),
                         rgnav::InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RoomScoringTest);
