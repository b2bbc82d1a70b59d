// Tests the freespace grid of a region (thesis 5.2, "freespace map"): a simulated rectangular room
// gives its area, centroid and main axes; beams through a door gateway leave no freespace behind
// it; the 1-bit map is about area / 0.15^2 / 8 bytes; merging the grids of two halves of the
// scans gives the grid of all; the grid grows within its bound; invalid input is a typed error.
#include "core/rgmap/describe/RegionFreespace.h"

#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"
#include "core/rgmap/describe/FreespaceMoments.h"
#include "core/rgmap/describe/testing/RoomScans.h"

using Eigen::AlignedBox2d;
using Eigen::Vector2d;
using rgnav::FreespaceCell;
using rgnav::FreespaceConfig;
using rgnav::GatewaySegment;
using rgnav::LaserScan;
using rgnav::Pose2D;
using rgnav::RegionFreespace;
namespace t = rgnav::testing;

namespace {

// A 7 x 4.4 m room, not aligned with the 15 cm lattice.
const AlignedBox2d kRoom(Vector2d(-2.03, -1.27), Vector2d(4.97, 3.13));

RegionFreespace freespaceOf(const std::vector<t::Wall>& walls, const std::vector<Pose2D>& poses,
                            const std::vector<GatewaySegment>& gateways = {}, double noise = 0.005) {
  RegionFreespace freespace;
  const auto scans = t::scansFrom(walls, poses, noise);
  for (std::size_t k = 0; k < scans.size(); ++k) freespace.addScan(scans[k], poses[k], gateways);
  return freespace;
}

std::size_t count(const RegionFreespace& f, FreespaceCell state) {
  std::size_t n = 0;
  const auto& w = f.window();
  for (int j = w.row0; j < w.row0 + w.height; ++j)
    for (int i = w.col0; i < w.col0 + w.width; ++i) n += f.cell(i, j) == state;
  return n;
}

}  // namespace

class RegionFreespaceTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RegionFreespaceTest);
  CPPUNIT_TEST(roomAreaCentroidAndAxes);
  CPPUNIT_TEST(beamsThroughDoorGatewayAreCut);
  CPPUNIT_TEST(bitmapBytesFollowArea);
  CPPUNIT_TEST(noReturnBeamsAreFreeUpToCap);
  CPPUNIT_TEST(passingBeamsClearAnObstacleThatLeft);
  CPPUNIT_TEST(mergeOfHalvesEqualsWhole);
  CPPUNIT_TEST(mergeAcrossFrames);
  CPPUNIT_TEST(growsWithinMaxExtent);
  CPPUNIT_TEST(mergeBeyondMaxExtentKeepsWhatFits);
  CPPUNIT_TEST(invalidInputIsTypedError);
  CPPUNIT_TEST_SUITE_END();

 public:
  void roomAreaCentroidAndAxes() {
    const auto f = freespaceOf(t::roomWalls(kRoom), t::roomPoses(kRoom, 0.6, 5, 3));
    const auto m = rgnav::freespaceMoments(f);
    const double area = kRoom.volume();
    CPPUNIT_ASSERT_DOUBLES_EQUAL(area, m.areaM2, 0.02 * area);
    // The walls are the occupied cells: one 15 cm cell thick along the outline.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2 * (7.0 + 4.4) / 0.15, double(count(f, FreespaceCell::Occupied)), 8.0);
    CPPUNIT_ASSERT((m.centroid - kRoom.center()).norm() < 0.05);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, std::min(m.majorAxisAngleRad, M_PI - m.majorAxisAngleRad), 0.01);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(7.0 * 7.0 / 12, m.majorVariance, 0.05 * 7.0 * 7.0 / 12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.4 * 4.4 / 12, m.minorVariance, 0.06 * 4.4 * 4.4 / 12);
  }

  void beamsThroughDoorGatewayAreCut() {
    // A door from y = 0.5 to 1.5 in the east wall (x = 4.97) opens into a hall 6 m deep.
    auto walls = t::roomWalls(kRoom, t::Door{0.5, 1.5});
    const std::vector<t::Wall> hall{{{4.97, -4.0}, {10.97, -4.0}}, {{10.97, -4.0}, {10.97, 6.0}},
                                    {{10.97, 6.0}, {4.97, 6.0}},   {{4.97, 6.0}, {4.97, 3.13}},
                                    {{4.97, -1.27}, {4.97, -4.0}}};
    walls.insert(walls.end(), hall.begin(), hall.end());
    const auto poses = t::roomPoses(kRoom, 0.6, 5, 3);
    const std::vector<GatewaySegment> door{{{4.97, 0.5}, {4.97, 1.5}}};
    const auto behind = [](const RegionFreespace& f) {
      std::size_t n = 0;
      const auto& w = f.window();
      for (int j = w.row0; j < w.row0 + w.height; ++j)
        for (int i = w.col0; i < w.col0 + w.width; ++i)
          n += f.cell(i, j) != FreespaceCell::Unknown && f.cellCenter(i, j).x() > 4.97 + f.cellSizeM();
      return n;
    };
    // Without the gateway the hall is seen through the door; with it, nothing behind the door
    // line is known, not even the obstacles there.
    CPPUNIT_ASSERT(behind(freespaceOf(walls, poses)) > 100);
    const auto cut = freespaceOf(walls, poses, door);
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), behind(cut));
    // The doorway itself is free up to the gateway line.
    CPPUNIT_ASSERT(cut.cell(cut.cellOf({4.9, 1.0}).i, cut.cellOf({4.9, 1.0}).j) == FreespaceCell::Free);
  }

  void bitmapBytesFollowArea() {
    // Thesis 5.2: about 200 bytes for a 30 m² region at 15 cm.
    const AlignedBox2d room(Vector2d(0.02, 0.04), Vector2d(6.02, 5.04));
    const auto map = freespaceOf(t::roomWalls(room), t::roomPoses(room, 0.6, 4, 4)).bitmap();
    const double expected = room.volume() / (0.15 * 0.15) / 8.0;
    CPPUNIT_ASSERT_DOUBLES_EQUAL(expected, double(map.bytes.size()), 0.1 * expected);
    CPPUNIT_ASSERT_EQUAL((std::size_t(map.width) * std::size_t(map.height) + 7) / 8, map.bytes.size());
    CPPUNIT_ASSERT(map.bytes.size() <= 200);
    // The bits are row-major, least significant bit first, from the lower left cell.
    for (int row = 0; row < map.height; ++row)
      for (int col = 0; col < map.width; ++col) {
        const std::size_t k = std::size_t(row) * std::size_t(map.width) + std::size_t(col);
        CPPUNIT_ASSERT_EQUAL(bool((map.bytes[k / 8] >> (k % 8)) & 1), map.isFree(col, row));
        CPPUNIT_ASSERT_EQUAL(map.isFree(col, row), map.isFreeAt(map.cellCenter(col, row)));
      }
    CPPUNIT_ASSERT(map.isFreeAt(room.center()));
    CPPUNIT_ASSERT(!map.isFreeAt(room.max() + Vector2d(0.5, 0.5)));
  }

  void noReturnBeamsAreFreeUpToCap() {
    // One scan of 720 beams without return all round: a free disc of radius 3 m, no obstacle.
    LaserScan scan;
    scan.startAngle = -M_PI;
    scan.angleIncrement = M_PI / 360;
    scan.maxRange = 30.0;
    scan.ranges.assign(720, LaserScan::kNoReturn);
    RegionFreespace f;
    f.addScan(scan, {0.4, 0.3, 0.2}, {});
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), count(f, FreespaceCell::Occupied));
    const double area = double(count(f, FreespaceCell::Free)) * 0.15 * 0.15;
    CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI * 9.0, area, 0.06 * M_PI * 9.0);
    CPPUNIT_ASSERT(f.cell(f.cellOf({0.4 + 2.8, 0.3}).i, f.cellOf({0.4 + 2.8, 0.3}).j) == FreespaceCell::Free);
    CPPUNIT_ASSERT(f.cell(f.cellOf({0.4 + 3.2, 0.3}).i, f.cellOf({0.4 + 3.2, 0.3}).j) == FreespaceCell::Unknown);
  }

  void passingBeamsClearAnObstacleThatLeft() {
    // A person 1 m ahead in two scans, then gone (the wall 3 m ahead is seen) in eight.
    LaserScan scan;
    scan.angleIncrement = 0.001;
    scan.maxRange = 30.0;
    RegionFreespace f;
    const auto person = f.cellOf({1.0, 0.0});
    scan.ranges = {1.0f};
    for (int k = 0; k < 2; ++k) f.addScan(scan, {}, {});
    CPPUNIT_ASSERT(f.cell(person.i, person.j) == FreespaceCell::Occupied);
    scan.ranges = {3.0f};
    for (int k = 0; k < 7; ++k) f.addScan(scan, {}, {});
    CPPUNIT_ASSERT(f.cell(person.i, person.j) == FreespaceCell::Occupied);  // 7 < 4 * 2 passes
    f.addScan(scan, {}, {});
    CPPUNIT_ASSERT(f.cell(person.i, person.j) == FreespaceCell::Free);
    CPPUNIT_ASSERT(f.cell(f.cellOf({3.0, 0.0}).i, 0) == FreespaceCell::Occupied);
  }

  void mergeOfHalvesEqualsWhole() {
    const auto walls = t::roomWalls(kRoom, t::Door{0.5, 1.5});
    const auto poses = t::roomPoses(kRoom, 0.6, 5, 3);
    const auto scans = t::scansFrom(walls, poses, 0.005);
    const std::vector<GatewaySegment> door{{{4.97, 0.5}, {4.97, 1.5}}};
    RegionFreespace whole, first, second;
    for (std::size_t k = 0; k < scans.size(); ++k) {
      whole.addScan(scans[k], poses[k], door);
      (k < scans.size() / 2 ? first : second).addScan(scans[k], poses[k], door);
    }
    first.mergeFrom(second, {});
    CPPUNIT_ASSERT(whole.bitmap() == first.bitmap());
    CPPUNIT_ASSERT_EQUAL(whole.scanCount(), first.scanCount());
    for (int j = whole.window().row0 - 2; j < whole.window().row0 + whole.window().height + 2; ++j)
      for (int i = whole.window().col0 - 2; i < whole.window().col0 + whole.window().width + 2; ++i)
        CPPUNIT_ASSERT(whole.cell(i, j) == first.cell(i, j));
  }

  void mergeAcrossFrames() {
    // The second half of the scans is taken in the frame of another region whose origin lies at
    // (3, 1, 30 degrees) in this one; merged with that pose, it gives nearly the same freespace.
    const auto walls = t::roomWalls(kRoom);
    const auto poses = t::roomPoses(kRoom, 0.6, 5, 3);
    const auto scans = t::scansFrom(walls, poses, 0.005);
    const Pose2D otherInThis{3.0, 1.0, M_PI / 6};
    RegionFreespace whole, mine, other;
    for (std::size_t k = 0; k < scans.size(); ++k) {
      whole.addScan(scans[k], poses[k], {});
      if (k % 2 == 0)
        mine.addScan(scans[k], poses[k], {});
      else
        other.addScan(scans[k], rgnav::between(otherInThis, poses[k]), {});
    }
    mine.mergeFrom(other, otherInThis);
    std::size_t both = 0, either = 0;
    for (int j = whole.window().row0; j < whole.window().row0 + whole.window().height; ++j)
      for (int i = whole.window().col0; i < whole.window().col0 + whole.window().width; ++i) {
        const bool a = whole.cell(i, j) == FreespaceCell::Free, b = mine.cell(i, j) == FreespaceCell::Free;
        both += a && b;
        either += a || b;
      }
    CPPUNIT_ASSERT(double(both) / double(either) > 0.97);
  }

  // A region that outgrows maxExtentM keeps what it has; beams are cut at the border.
  void growsWithinMaxExtent() {
    FreespaceConfig config;
    config.maxExtentM = 20.0;
    RegionFreespace f(config);
    LaserScan scan;
    scan.angleIncrement = 0.01;
    scan.maxRange = 30.0;
    scan.ranges = {2.0f};
    f.addScan(scan, {}, {});
    const auto first = f.window();
    f.addScan(scan, {10.0, 0.0, 0.0}, {});  // grows towards +x
    CPPUNIT_ASSERT(f.window().width > first.width);
    CPPUNIT_ASSERT(f.window().width * 0.15 <= 20.0);
    CPPUNIT_ASSERT(f.cell(f.cellOf({1.0, 0.0}).i, 0) == FreespaceCell::Free);  // kept while growing
    CPPUNIT_ASSERT(f.cell(f.cellOf({12.0, 0.0}).i, 0) == FreespaceCell::Occupied);
    // A sensor 25 m away from the first scan does not fit with the cells the grid holds: the
    // scan adds nothing and is counted.
    const auto before = f.bitmap();
    const auto window = f.window();
    CPPUNIT_ASSERT(!f.addScan(scan, {-13.0, 0.0, 0.0}, {}));
    CPPUNIT_ASSERT(before == f.bitmap());
    CPPUNIT_ASSERT_EQUAL(window.col0, f.window().col0);
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), f.scanCount());
    // A sensor that fits, with a beam reaching beyond the largest grid: the grid grows to
    // maxExtentM, the beam is cut at its border (free up to there, no hit beyond).
    LaserScan far = scan;
    far.ranges = {15.0f};
    CPPUNIT_ASSERT(f.addScan(far, {-1.0, 0.0, M_PI}, {}));
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), f.scanCount());
    CPPUNIT_ASSERT(f.window().width * 0.15 > 19.5);
    const int border = f.window().col0;
    for (int i = border; i < f.cellOf({-1.0, 0.0}).i; ++i)  // the cut beam marks no hit at the border
      CPPUNIT_ASSERT(f.cell(i, 0) == FreespaceCell::Free);
  }

  // Merging a region that does not fit beside this one keeps this grid's cells and takes the
  // part of the other's that fits.
  void mergeBeyondMaxExtentKeepsWhatFits() {
    FreespaceConfig config;
    config.maxExtentM = 20.0;
    LaserScan scan;
    scan.angleIncrement = 0.01;
    scan.maxRange = 30.0;
    scan.ranges = {2.0f};
    RegionFreespace mine(config), other(config);
    mine.addScan(scan, {}, {});
    other.addScan(scan, {}, {});
    mine.mergeFrom(other, {17.0, 0.0, 0.0});  // together 19 m of beams plus margins: more than fits
    CPPUNIT_ASSERT(mine.window().width * 0.15 <= 20.0);
    CPPUNIT_ASSERT(mine.cell(mine.cellOf({1.0, 0.0}).i, 0) == FreespaceCell::Free);
    CPPUNIT_ASSERT(mine.cell(mine.cellOf({17.2, 0.0}).i, 0) == FreespaceCell::Free);  // taken from the other
    CPPUNIT_ASSERT(mine.cell(mine.cellOf({18.5, 0.0}).i, 0) == FreespaceCell::Unknown);  // beyond what fits
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), mine.scanCount());
  }

  void invalidInputIsTypedError() {
    const auto bad = [](auto change) {
      FreespaceConfig c;
      change(c);
      return c;
    };
    CPPUNIT_ASSERT_THROW(RegionFreespace(bad([](auto& c) { c.cellSizeM = 0.0; })), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(RegionFreespace(bad([](auto& c) { c.cellSizeM = std::nan(""); })), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(RegionFreespace(bad([](auto& c) { c.noReturnFreeRangeM = -1.0; })), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(RegionFreespace(bad([](auto& c) { c.freePerHit = -1.0; })), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(RegionFreespace(bad([](auto& c) { c.maxExtentM = 1e6; })), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(RegionFreespace(bad([](auto& c) { c.maxExtentM = 0.1; })), rgnav::ConfigError);

    RegionFreespace f;
    LaserScan scan;
    scan.angleIncrement = 0.01;
    scan.ranges = {2.0f};
    CPPUNIT_ASSERT_THROW(f.addScan(scan, {std::nan(""), 0.0, 0.0}, {}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(f.addScan(scan, {1e12, 0.0, 0.0}, {}), rgnav::InvalidArgumentError);
    rgnav::RegionBeams beams;
    beams.beams.push_back({Vector2d(std::nan(""), 0.0), true});
    CPPUNIT_ASSERT_THROW(f.addBeams(beams), rgnav::InvalidArgumentError);
    beams.beams = {{Vector2d(1.0, 0.0), true}};
    beams.origin = Vector2d(0.0, INFINITY);
    CPPUNIT_ASSERT_THROW(f.addBeams(beams), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), f.scanCount());
    CPPUNIT_ASSERT(f.window().empty());
    f.addScan(scan, {}, {});
    CPPUNIT_ASSERT_THROW(f.mergeFrom(f, {}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(f.mergeFrom(RegionFreespace(), {0.0, 0.0, std::nan("")}), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(RegionFreespaceTest);
