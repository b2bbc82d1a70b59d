// Tests registerScan (correlative search + point-to-line refinement): known offsets recovered on
// synthetic scans of a box room and a corridor, and on a real Intel keyframe pair whose raw
// odometry is 9 cm / 5 degrees off the GMapping-corrected relative pose; with the loop closer's
// test for undetermined directions, a featureless corridor's axis keeps the guess's position and
// no point information, while the box room and the corridor with door recesses stay determined.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/logs/IntelJsonLogReader.h"
#include "core/logs/LogTestFiles.h"
#include "core/slam/ReferenceMap.h"
#include "core/slam/ScanPoints.h"
#include "core/slam/ScanRegistration.h"
#include "core/slam/testing/SyntheticWorld.h"

using rgnav::Pose2D;

namespace {

const rgnav::SlamConfig kConfig;

rgnav::ReferenceMap referenceOf(const rgnav::LaserScan& scan, const Pose2D& pose) {
  rgnav::ReferenceMap reference(kConfig.local.grid, rgnav::pyramidLevelsFor(0.5, kConfig.local.grid.resolution));
  const auto points = rgnav::scanToPoints(scan, kConfig.points);
  reference.add(points, rgnav::estimateNormals(points, kConfig.points), pose);
  reference.build();
  return reference;
}

rgnav::RegistrationCriteria criteria() { return {{0.5, 0.3}, 0.3, 0.3}; }
rgnav::RegistrationCriteria loopCriteria() { return {{0.5, 0.3}, 0.3, 0.3, kConfig.loop.undetermined}; }

// Two parallel walls 2 m apart along x, their ends far beyond the laser's range.
rgnav::testing::World featurelessCorridor() {
  return {{{-100.0, -1.0}, {100.0, -1.0}}, {{-100.0, 1.0}, {100.0, 1.0}}};
}

double translationError(const Pose2D& a, const Pose2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }
double rotationErrorDeg(const Pose2D& a, const Pose2D& b) { return std::abs(rgnav::normalizeAngle(a.theta - b.theta)) * 180.0 / M_PI; }

// Registers the scan taken at `truth` against the one taken at `from`, starting from `from`.
void assertRecovers(const rgnav::testing::World& world, const Pose2D& from, const Pose2D& truth,
                    const rgnav::RegistrationCriteria& criteria = ::criteria()) {
  const auto reference = referenceOf(rgnav::testing::simulateScan(world, from), from);
  const auto query = rgnav::scanToPoints(rgnav::testing::simulateScan(world, truth), kConfig.points);
  const auto result = rgnav::registerScan(reference, query, from, criteria, kConfig.icp);
  CPPUNIT_ASSERT(result.has_value());
  CPPUNIT_ASSERT(translationError(result->pose, truth) < 0.005);
  CPPUNIT_ASSERT(rotationErrorDeg(result->pose, truth) < 0.1);
  CPPUNIT_ASSERT(result->inlierFraction > 0.75);
}

}  // namespace

class ScanRegistrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ScanRegistrationTest);
  CPPUNIT_TEST(recoversOffsetInBoxRoom);
  CPPUNIT_TEST(recoversOffsetInCorridor);
  CPPUNIT_TEST(recoversRealIntelPair);
  CPPUNIT_TEST(failsOutsideTheWindow);
  CPPUNIT_TEST(keepsDeterminedDirections);
  CPPUNIT_TEST(dropsTheAxisOfAFeaturelessCorridor);
  CPPUNIT_TEST_SUITE_END();

 public:
  void recoversOffsetInBoxRoom() {
    assertRecovers(rgnav::testing::boxWorld(), {-1.0, 0.5, 0.3}, {-0.7, 0.32, 0.3 + 12.0 * M_PI / 180.0});
    assertRecovers(rgnav::testing::boxWorld(), {0.5, -1.0, -2.0}, {0.1, -1.2, -2.0 - 0.2});
  }
  void recoversOffsetInCorridor() {
    assertRecovers(rgnav::testing::corridorWorld(), {0.0, 0.0, 0.0}, {0.35, 0.1, 0.1});
    assertRecovers(rgnav::testing::corridorWorld(), {-4.0, 0.2, M_PI}, {-4.3, 0.1, M_PI - 0.15});
  }
  void recoversRealIntelPair() {
    rgnav::LogReaderOptions options;
    options.correctedPosesPath = rgnav::testing::sharedData("laser/derived/xiaofeng-intel_corrected_log.json.xz");
    rgnav::IntelJsonLogReader reader(rgnav::testing::sharedData("laser/derived/xiaofeng-intel_gfs.json.xz"), options);
    const auto scans = rgnav::testing::readAll(reader).scans;
    const rgnav::LaserScan& a = scans.at(20);
    const rgnav::LaserScan& b = scans.at(21);
    const Pose2D truth = rgnav::between(a.sensorPose, b.sensorPose);  // GMapping-corrected
    const Pose2D guess = rgnav::between(a.odometry, b.odometry);      // raw odometry
    CPPUNIT_ASSERT(translationError(guess, truth) > 0.08 && rotationErrorDeg(guess, truth) > 5.0);
    const auto reference = referenceOf(a, {});
    const auto query = rgnav::scanToPoints(b, kConfig.points);
    const auto result = rgnav::registerScan(reference, query, guess, criteria(), kConfig.icp);
    CPPUNIT_ASSERT(result.has_value());
    CPPUNIT_ASSERT(translationError(result->pose, truth) < 0.03);
    CPPUNIT_ASSERT(rotationErrorDeg(result->pose, truth) < 1.0);
  }
  void failsOutsideTheWindow() {
    const auto world = rgnav::testing::boxWorld();
    const Pose2D from{-1.0, 0.5, 0.3};
    const auto reference = referenceOf(rgnav::testing::simulateScan(world, from), from);
    const auto query = rgnav::scanToPoints(rgnav::testing::simulateScan(world, {1.5, -1.5, 2.0}), kConfig.points);
    CPPUNIT_ASSERT(!rgnav::registerScan(reference, query, from, {{0.2, 0.1}, 0.6, 0.6}, kConfig.icp).has_value());
  }
  void keepsDeterminedDirections() {
    assertRecovers(rgnav::testing::boxWorld(), {0.5, -1.0, -2.0}, {0.1, -1.2, -2.0 - 0.2}, loopCriteria());
    assertRecovers(rgnav::testing::corridorWorld(), {0.0, 0.0, 0.0}, {0.35, 0.1, 0.1}, loopCriteria());
  }
  void dropsTheAxisOfAFeaturelessCorridor() {
    const auto world = featurelessCorridor();
    const Pose2D from{0.0, 0.0, 0.0};
    const Pose2D truth{0.3, 0.1, 0.05};
    const auto reference = referenceOf(rgnav::testing::simulateScan(world, from), from);
    const auto query = rgnav::scanToPoints(rgnav::testing::simulateScan(world, truth), kConfig.points);
    const auto result = rgnav::registerScan(reference, query, from, loopCriteria(), kConfig.icp);
    CPPUNIT_ASSERT(result.has_value());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(from.x, result->pose.x, 1e-9);  // the guess's position along the axis
    CPPUNIT_ASSERT_DOUBLES_EQUAL(truth.y, result->pose.y, 0.005);
    CPPUNIT_ASSERT(rotationErrorDeg(result->pose, truth) < 0.1);
    const double windowFloor = 1.0 / (0.5 * 0.5);  // all that is left along the axis
    CPPUNIT_ASSERT_DOUBLES_EQUAL(windowFloor, result->information(0, 0), 1e-6);
    CPPUNIT_ASSERT(result->information(1, 1) > 100.0 * windowFloor);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(ScanRegistrationTest);
