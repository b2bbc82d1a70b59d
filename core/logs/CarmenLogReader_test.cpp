// Tests CarmenLogReader on the real logs of the shared data folder: record counts, ID sequences,
// beam geometry of FLASER (180/181/360/361 beams) and ROBOTLASER1, and the statistics.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <vector>

#include "core/logs/CarmenLogReader.h"
#include "core/logs/LogTestFiles.h"
#include "core/logs/OpenLog.h"

using rgnav::CarmenLogReader;
using rgnav::LaserScan;
using rgnav::testing::LogContents;
using rgnav::testing::readAll;

namespace {

constexpr double kDegree = M_PI / 180.0;

LogContents readCarmen(const std::string& relative) {
  CarmenLogReader reader(rgnav::testing::sharedData(relative));
  return readAll(reader);
}

template <typename Record>
void assertIdsCount(const std::vector<Record>& records) {
  for (std::size_t i = 0; i < records.size(); ++i) {
    CPPUNIT_ASSERT_EQUAL(rgnav::DataId{i + 1}, records[i].id);
  }
}

void assertCleanStats(const rgnav::LogStats& stats) {
  CPPUNIT_ASSERT_EQUAL(std::size_t{0}, stats.malformedLines);
  CPPUNIT_ASSERT_EQUAL(std::size_t{0}, stats.overLongLines);
  CPPUNIT_ASSERT_EQUAL(std::size_t{0}, stats.unknownMessages);
  CPPUNIT_ASSERT_EQUAL(std::size_t{0}, stats.droppedRanges);
  CPPUNIT_ASSERT(stats.problems.empty());
}

// Every scan has `beams` beams, spread as FLASER says.
void assertFlaserGeometry(const LogContents& log, std::size_t beams, double increment,
                          double lastAngle) {
  for (const auto& scan : log.scans) {
    CPPUNIT_ASSERT_EQUAL(beams, scan.ranges.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-M_PI / 2, scan.startAngle, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(increment, scan.angleIncrement, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(lastAngle, scan.startAngle + (beams - 1) * scan.angleIncrement,
                                 1e-9);
    CPPUNIT_ASSERT_EQUAL(80.0, scan.maxRange);
  }
}

}  // namespace

class CarmenLogReaderTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CarmenLogReaderTest);
  CPPUNIT_TEST(intelCorrectedLog);
  CPPUNIT_TEST(flirtlibRobotLaserLog);
  CPPUNIT_TEST(freiburg101Has360BeamsAtHalfDegree);
  CPPUNIT_TEST(seattleHas361BeamsAtHalfDegreeBothEnds);
  CPPUNIT_TEST(orebroHas181BeamsAtOneDegreeBothEnds);
  CPPUNIT_TEST(openLogPicksCarmenReader);
  CPPUNIT_TEST_SUITE_END();

 public:
  void intelCorrectedLog() {
    const LogContents log = readCarmen("laser/corrected/intel-corrected.log.gz");
    CPPUNIT_ASSERT_EQUAL(std::size_t{910}, log.scans.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t{14541}, log.odometry.size());
    assertIdsCount(log.scans);
    assertIdsCount(log.odometry);
    assertFlaserGeometry(log, 180, kDegree, 89 * kDegree);
    assertCleanStats(log.stats);
    CPPUNIT_ASSERT_EQUAL(std::size_t{16365}, log.stats.lines);
    CPPUNIT_ASSERT_EQUAL(std::size_t{910}, log.stats.scans);
    CPPUNIT_ASSERT_EQUAL(std::size_t{14541}, log.stats.odometryReadings);
    CPPUNIT_ASSERT_EQUAL(std::size_t{4172}, log.stats.noReturnRanges);

    const LaserScan& first = log.scans.front();
    CPPUNIT_ASSERT_DOUBLES_EQUAL(32.9068, first.stamp, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.600266, first.sensorPose.x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-0.0320327, first.sensorPose.y, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-0.354665, first.sensorPose.theta, 1e-9);
    CPPUNIT_ASSERT(first.odometry == first.sensorPose);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.09f, first.ranges.front(), 1e-6);
  }

  void flirtlibRobotLaserLog() {
    const LogContents log = readCarmen("laser/graph/flirtlib-intel-lab.log.xz");
    CPPUNIT_ASSERT_EQUAL(std::size_t{2672}, log.scans.size());
    CPPUNIT_ASSERT(log.odometry.empty());
    assertIdsCount(log.scans);
    assertCleanStats(log.stats);
    CPPUNIT_ASSERT_EQUAL(std::size_t{10677}, log.stats.noReturnRanges);
    for (const auto& scan : log.scans) {
      CPPUNIT_ASSERT_EQUAL(std::size_t{180}, scan.ranges.size());
      CPPUNIT_ASSERT_DOUBLES_EQUAL(-1.570796, scan.startAngle, 1e-12);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(0.017453, scan.angleIncrement, 1e-12);
      CPPUNIT_ASSERT_EQUAL(50.0, scan.maxRange);
    }
    const LaserScan& first = log.scans.front();
    CPPUNIT_ASSERT_DOUBLES_EQUAL(700.430084, first.stamp, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.775, first.odometry.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-1.686332, first.sensorPose.theta, 1e-12);
    CPPUNIT_ASSERT(std::isinf(first.ranges.front()));
  }

  void freiburg101Has360BeamsAtHalfDegree() {
    const LogContents log = readCarmen("laser/corrected/freiburg-101-corrected.log.gz");
    CPPUNIT_ASSERT_EQUAL(std::size_t{292}, log.scans.size());
    assertFlaserGeometry(log, 360, 0.5 * kDegree, 89.5 * kDegree);
    assertCleanStats(log.stats);
  }

  void seattleHas361BeamsAtHalfDegreeBothEnds() {
    const LogContents log = readCarmen("laser/corrected/seattle-corrected.log.gz");
    CPPUNIT_ASSERT_EQUAL(std::size_t{241}, log.scans.size());
    assertFlaserGeometry(log, 361, 0.5 * kDegree, M_PI / 2);
    assertCleanStats(log.stats);
  }

  void orebroHas181BeamsAtOneDegreeBothEnds() {
    const LogContents log = readCarmen("laser/corrected/orebro-corrected.log.gz");
    CPPUNIT_ASSERT_EQUAL(std::size_t{237}, log.scans.size());
    assertFlaserGeometry(log, 181, kDegree, M_PI / 2);
    assertCleanStats(log.stats);
  }

  void openLogPicksCarmenReader() {
    const auto source =
        rgnav::openLog(rgnav::testing::sharedData("laser/corrected/intel-corrected.log.gz"));
    CPPUNIT_ASSERT(dynamic_cast<CarmenLogReader*>(source.get()) != nullptr);
    CPPUNIT_ASSERT_EQUAL(std::size_t{910}, readAll(*source).scans.size());
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(CarmenLogReaderTest);
