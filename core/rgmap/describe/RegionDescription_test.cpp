// Tests the description of a simulated region (thesis 2.1.1, table 2.1) end to end, from scans
// through RegionEvidence and RegionLineMap: bounding rectangles of the measurements inside the
// region, freespace moments, main directions, accuracy for exact and shifted lines, completeness of
// a closed room, a room with a door gateway and rooms with an unseen side, the freespace byte size,
// and the description of merged evidence.
#include "core/rgmap/describe/RegionDescription.h"

#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"
#include "core/lines/RegionLineMap.h"
#include "core/lines/ScanPoints.h"
#include "core/rgmap/describe/testing/RoomScans.h"

using Eigen::AlignedBox2d;
using Eigen::Vector2d;
using rgnav::GatewaySegment;
using rgnav::LineSegment;
using rgnav::Pose2D;
using rgnav::RegionDescription;
using rgnav::RegionEvidence;
namespace t = rgnav::testing;

namespace {

const AlignedBox2d kRoom(Vector2d(-2.03, -1.27), Vector2d(4.97, 3.13));  // 7 x 4.4 m
const t::Door kDoor{0.5, 1.5};                                             // in the east wall
const std::vector<GatewaySegment> kDoorGateway{{{4.97, 0.5}, {4.97, 1.5}}};

// Scans of `walls` from `poses` given in the world, added in a region frame whose pose in the
// world is `regionInWorld`; the region's line map is built alongside.
struct Region {
  RegionEvidence evidence;
  rgnav::RegionLineMap lines;
};
Region regionOf(const std::vector<t::Wall>& walls, const std::vector<Pose2D>& poses,
                const std::vector<GatewaySegment>& gateways = {}, const Pose2D& regionInWorld = {}) {
  Region region;
  const auto scans = t::scansFrom(walls, poses, 0.005);
  for (std::size_t k = 0; k < scans.size(); ++k) {
    const Pose2D inRegion = rgnav::between(regionInWorld, poses[k]);
    region.evidence.addScan(scans[k], inRegion, gateways);
    region.lines.addScan(scans[k], inRegion);
  }
  return region;
}

RegionDescription describe(const Region& r, const std::vector<GatewaySegment>& gateways = {}) {
  return rgnav::describeRegion(r.evidence, r.lines.lines(), gateways);
}

// The room's walls as map lines, shifted outwards by `offset`.
std::vector<LineSegment> wallLines(double offset) {
  const Vector2d lo = kRoom.min() - Vector2d::Constant(offset), hi = kRoom.max() + Vector2d::Constant(offset);
  return {rgnav::segmentFromEndpoints(1, lo, {hi.x(), lo.y()}), rgnav::segmentFromEndpoints(2, {hi.x(), lo.y()}, hi),
          rgnav::segmentFromEndpoints(3, hi, {lo.x(), hi.y()}), rgnav::segmentFromEndpoints(4, {lo.x(), hi.y()}, lo)};
}

}  // namespace

class RegionDescriptionTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RegionDescriptionTest);
  CPPUNIT_TEST(closedRoom);
  CPPUNIT_TEST(rotatedRoomKeepsItsShape);
  CPPUNIT_TEST(doorGatewayClosesTheRegion);
  CPPUNIT_TEST(unseenSideLowersCompleteness);
  CPPUNIT_TEST(accuracyOfExactAndShiftedLines);
  CPPUNIT_TEST(mergedEvidenceDescribesTheWhole);
  CPPUNIT_TEST(emptyEvidenceAndBadInput);
  CPPUNIT_TEST_SUITE_END();

 public:
  void closedRoom() {
    const auto region = regionOf(t::roomWalls(kRoom), t::roomPoses(kRoom, 0.6, 5, 3));
    const auto d = describe(region);
    // Bounding box of the measurements: the walls.
    CPPUNIT_ASSERT((d.boundingBox.min() - kRoom.min()).norm() < 0.03);
    CPPUNIT_ASSERT((d.boundingBox.max() - kRoom.max()).norm() < 0.03);
    CPPUNIT_ASSERT(d.minimumAreaBox);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(7.0, d.minimumAreaBox->lengthM, 0.03);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.4, d.minimumAreaBox->widthM, 0.03);
    // Freespace: area, centroid (also relative to the box), main axes.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(30.8, d.moments.areaM2, 0.02 * 30.8);
    // Within a third of a cell: where the walls cut their cells decides how much of them counts.
    CPPUNIT_ASSERT((d.moments.centroid - kRoom.center()).norm() < 0.05);
    CPPUNIT_ASSERT((d.centroidInBox - Vector2d(0.5, 0.5)).norm() < 0.01);
    CPPUNIT_ASSERT(rgnav::orientationDifference(d.moments.majorAxisAngleRad, 0.0) < 0.01);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(49.0 / 12, d.moments.majorVariance, 0.03 * 49.0 / 12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.4 * 4.4 / 12, d.moments.minorVariance, 0.03 * 4.4 * 4.4 / 12);
    // Main directions of the walls: 0 and 90 degrees, the longer walls first.
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), d.mainDirections.size());
    CPPUNIT_ASSERT(rgnav::orientationDifference(d.mainDirections[0].angleRad, 0.0) < 0.005);
    CPPUNIT_ASSERT(rgnav::orientationDifference(d.mainDirections[1].angleRad, M_PI / 2) < 0.005);
    // The line map fits the scans; the room is fully explored.
    CPPUNIT_ASSERT(d.accuracy.inlierShare > 0.98);
    CPPUNIT_ASSERT(d.accuracy.rmsDistanceM < 0.02);
    CPPUNIT_ASSERT(d.completeness.completeness > 0.97);
    // 1 bit per 15 cm cell of the free cells' bounding box.
    CPPUNIT_ASSERT_EQUAL(d.freespace.bytes.size(), d.freespaceBytes());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(30.8 / (0.15 * 0.15) / 8, double(d.freespaceBytes()), 0.1 * 30.8 / (0.15 * 0.15) / 8);
    CPPUNIT_ASSERT_EQUAL(std::size_t(15), d.scanCount);
  }

  void rotatedRoomKeepsItsShape() {
    // The same room, but the region frame is turned by -35 degrees and shifted against the world,
    // so the room lies at 35 degrees in it: the axis-aligned box grows, the rest turns along.
    const Pose2D regionInWorld{1.0, -0.5, -35 * M_PI / 180};
    const auto d = describe(regionOf(t::roomWalls(kRoom), t::roomPoses(kRoom, 0.6, 5, 3), {}, regionInWorld));
    const double turned = 35 * M_PI / 180;
    CPPUNIT_ASSERT(rgnav::orientationDifference(d.minimumAreaBox->angleRad, turned) < 0.01);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(7.0, d.minimumAreaBox->lengthM, 0.03);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.4, d.minimumAreaBox->widthM, 0.03);
    const Vector2d center = rgnav::transformPoint(rgnav::inverse(regionInWorld), kRoom.center());
    CPPUNIT_ASSERT((d.minimumAreaBox->center - center).norm() < 0.03);
    const double width = 7.0 * std::cos(turned) + 4.4 * std::sin(turned);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(width, d.boundingBox.sizes().x(), 0.05);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(30.8, d.moments.areaM2, 0.03 * 30.8);
    CPPUNIT_ASSERT((d.moments.centroid - center).norm() < 0.05);
    CPPUNIT_ASSERT(rgnav::orientationDifference(d.moments.majorAxisAngleRad, turned) < 0.02);
    CPPUNIT_ASSERT(rgnav::orientationDifference(d.mainDirections[0].angleRad, turned) < 0.005);
    CPPUNIT_ASSERT(rgnav::orientationDifference(d.mainDirections[1].angleRad, turned + M_PI / 2) < 0.005);
    CPPUNIT_ASSERT(d.completeness.completeness > 0.97);  // walls across the lattice close it as well
  }

  void doorGatewayClosesTheRegion() {
    // Behind the door lies a hall; beams through the door are cut at the gateway, so neither the
    // bounding box nor the freespace reaches into the hall, and the door does not count as open.
    auto walls = t::roomWalls(kRoom, kDoor);
    const std::vector<t::Wall> hall{{{4.97, -4.0}, {10.97, -4.0}}, {{10.97, -4.0}, {10.97, 6.0}},
                                    {{10.97, 6.0}, {4.97, 6.0}},   {{4.97, 6.0}, {4.97, 3.13}},
                                    {{4.97, -1.27}, {4.97, -4.0}}};
    walls.insert(walls.end(), hall.begin(), hall.end());
    const auto poses = t::roomPoses(kRoom, 0.6, 5, 3);
    const auto withGateway = regionOf(walls, poses, kDoorGateway);
    const auto d = describe(withGateway, kDoorGateway);
    CPPUNIT_ASSERT(d.boundingBox.max().x() < 4.97 + 0.03);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(30.8, d.moments.areaM2, 0.02 * 30.8);
    CPPUNIT_ASSERT(d.completeness.completeness > 0.97);
    // Without the gateway the hall is part of the region; told about the gateway only afterwards,
    // the description still sees the hall as open space.
    const auto without = regionOf(walls, poses);
    CPPUNIT_ASSERT(describe(without).boundingBox.max().x() > 10.0);
    CPPUNIT_ASSERT(describe(without).moments.areaM2 > 35.0);
    CPPUNIT_ASSERT(describe(without, kDoorGateway).completeness.completeness < d.completeness.completeness);
  }

  void unseenSideLowersCompleteness() {
    // The north wall is missing: the beams there get no return and end in unexplored space.
    auto walls = t::roomWalls(kRoom);
    walls.erase(walls.begin() + 1);  // {ne, nw}
    const auto d = describe(regionOf(walls, t::roomPoses(kRoom, 0.6, 5, 3)));
    CPPUNIT_ASSERT(d.completeness.completeness < 0.75);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0 - d.completeness.completeness, d.completeness.frontierShare, 1e-12);
    // A room seen only from its west end, looking west: most of it was never seen.
    const auto half = describe(regionOf(t::roomWalls(kRoom), {{-1.5, 0.0, M_PI}, {-1.5, 2.0, M_PI}}));
    CPPUNIT_ASSERT(half.completeness.completeness < 0.75);
  }

  void accuracyOfExactAndShiftedLines() {
    const auto region = regionOf(t::roomWalls(kRoom), t::roomPoses(kRoom, 0.6, 5, 3));
    const auto& points = region.evidence.sample().points();
    CPPUNIT_ASSERT_EQUAL(std::size_t(2048), points.size());
    const auto exact = rgnav::lineMapAccuracy(points, wallLines(0.0));
    CPPUNIT_ASSERT(exact.inlierShare > 0.999);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.005, exact.rmsDistanceM, 0.001);  // the range noise
    const auto shifted = rgnav::lineMapAccuracy(points, wallLines(0.1));
    CPPUNIT_ASSERT(shifted.inlierShare < 0.05);
    CPPUNIT_ASSERT(shifted.meanDistanceM > 0.09);
    // The line map built from the scans fits about as well as the exact walls.
    const auto built = describe(region).accuracy;
    CPPUNIT_ASSERT(built.inlierShare > 0.98);
    CPPUNIT_ASSERT(built.rmsDistanceM < 2.0 * exact.rmsDistanceM + 0.005);
  }

  void mergedEvidenceDescribesTheWhole() {
    // Two regions (the room's west and east parts with their own frames) merged into one.
    const auto walls = t::roomWalls(kRoom);
    const auto west = t::roomPoses(AlignedBox2d(kRoom.min(), Vector2d(1.47, 3.13)), 0.6, 3, 3);
    const auto east = t::roomPoses(AlignedBox2d(Vector2d(1.47, -1.27), kRoom.max()), 0.6, 3, 3);
    const Pose2D eastInWest{3.0, 0.5, 0.4};
    auto a = regionOf(walls, west);
    const auto b = regionOf(walls, east, {}, eastInWest);
    a.evidence.mergeFrom(b.evidence, eastInWest);
    const auto d = rgnav::describeRegion(a.evidence, wallLines(0.0), {});
    CPPUNIT_ASSERT_DOUBLES_EQUAL(30.8, d.moments.areaM2, 0.03 * 30.8);
    CPPUNIT_ASSERT((d.boundingBox.min() - kRoom.min()).norm() < 0.03);
    CPPUNIT_ASSERT((d.boundingBox.max() - kRoom.max()).norm() < 0.03);
    CPPUNIT_ASSERT(d.accuracy.inlierShare > 0.999);
    CPPUNIT_ASSERT(d.completeness.completeness > 0.95);
    CPPUNIT_ASSERT_EQUAL(std::size_t(18), d.scanCount);
  }

  void emptyEvidenceAndBadInput() {
    const RegionEvidence empty;
    const auto d = rgnav::describeRegion(empty, {}, {});
    CPPUNIT_ASSERT(d.boundingBox.isEmpty());
    CPPUNIT_ASSERT(!d.minimumAreaBox);
    CPPUNIT_ASSERT_EQUAL(0.0, d.moments.areaM2);
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), d.freespaceBytes());
    CPPUNIT_ASSERT(d.mainDirections.empty());
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), d.accuracy.pointCount);
    CPPUNIT_ASSERT_EQUAL(0.0, d.completeness.completeness);

    rgnav::RegionEvidenceConfig config;
    config.samplePoints = 0;
    CPPUNIT_ASSERT_THROW(RegionEvidence{config}, rgnav::ConfigError);
    config = {};
    config.freespace.cellSizeM = -0.15;
    CPPUNIT_ASSERT_THROW(RegionEvidence{config}, rgnav::ConfigError);

    RegionEvidence evidence;
    const auto scan = t::scansFrom(t::roomWalls(kRoom), {{0, 0, 0}}).front();
    CPPUNIT_ASSERT_THROW(evidence.addScan(scan, {0, std::nan(""), 0}, {}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), evidence.sample().points().size());
    evidence.addScan(scan, {}, {});
    CPPUNIT_ASSERT_THROW(evidence.mergeFrom(evidence, {}), rgnav::InvalidArgumentError);
    const std::vector<GatewaySegment> bad{{{0, 0}, {INFINITY, 0}}};
    CPPUNIT_ASSERT_THROW(rgnav::describeRegion(evidence, {}, bad), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(RegionDescriptionTest);
