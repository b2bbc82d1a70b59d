// Tests the CARMEN writer: a written log reads back through CarmenLogReader (ranges to the
// millimetre, no-return and dropped beams, poses, stamps, ODOM velocities), a simulated run
// written twice with the same seed is byte-identical (and differs for another seed), and scans
// FLASER cannot express or a bad host are rejected.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "core/common/Errors.h"
#include "core/logs/CarmenLogReader.h"
#include "core/logs/FlaserGeometry.h"
#include "core/logs/LogTestFiles.h"
#include "core/sim/motion/CarmenLogWriter.h"
#include "core/sim/motion/DiffDriveRobot.h"
#include "core/sim/motion/OdometryNoiseModel.h"

using rgnav::CarmenLogWriter;
using rgnav::LaserScan;
using rgnav::OdometryReading;
using rgnav::Pose2D;

namespace {

LaserScan flaserScan(std::size_t beams) {
  LaserScan scan;
  scan.startAngle = rgnav::kFlaserStartAngle;
  scan.angleIncrement = rgnav::flaserAngleIncrement(beams);
  scan.maxRange = 80.0;
  scan.ranges.assign(beams, 1.0f);
  return scan;
}

// A short simulated run: a robot driving a circle, odometry with noise, ranges drawn at random
// (the laser is not this library's job), everything from `seed`.
std::string simulatedLog(std::uint64_t seed) {
  const rgnav::OccupancyGrid open(400, 400, 0.05, {-10.0, -10.0});
  rgnav::DiffDriveRobot robot(rgnav::DiffDriveConfig{}, {});
  rgnav::OdometryNoiseModel noise(rgnav::OdometryNoiseConfig{}, seed);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> range(0.1f, 30.0f);
  std::ostringstream out;
  CarmenLogWriter writer(out);
  Pose2D odometry{};
  robot.command({0.5, 0.3});
  for (int k = 1; k <= 50; ++k) {
    const Pose2D before = robot.pose();
    robot.step(0.1, open);
    odometry = noise.advance(odometry, before, robot.pose());
    const double stamp = 1000.0 + 0.1 * k;
    writer.write(OdometryReading{0, stamp, odometry, robot.velocity().translational, robot.velocity().rotational});
    LaserScan scan = flaserScan(181);
    for (float& r : scan.ranges) r = range(rng);
    scan.ranges[5] = LaserScan::kNoReturn;
    scan.stamp = stamp;
    scan.sensorPose = robot.pose();
    scan.odometry = odometry;
    writer.write(scan);
  }
  return out.str();
}

}  // namespace

class CarmenLogWriterTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CarmenLogWriterTest);
  CPPUNIT_TEST(roundTripsThroughReader);
  CPPUNIT_TEST(writesFixedFormat);
  CPPUNIT_TEST(sameSeedGivesByteIdenticalLog);
  CPPUNIT_TEST(rejectsWhatFlaserCannotExpress);
  CPPUNIT_TEST_SUITE_END();

 public:
  void roundTripsThroughReader() {
    std::ostringstream out;
    CarmenLogWriter writer(out);
    LaserScan scan = flaserScan(361);
    for (std::size_t i = 0; i < scan.ranges.size(); ++i) scan.ranges[i] = 0.5f + 0.0371f * float(i);
    scan.ranges[0] = LaserScan::kNoReturn;
    scan.ranges[1] = LaserScan::kInvalid;
    scan.ranges[2] = 0.0f;
    scan.stamp = 1234.567891;
    scan.sensorPose = {1.25, -3.5, 3.1};
    scan.odometry = {0.125, 7.0, -1.5};
    const OdometryReading odom{0, 1234.5, {2.0, -1.0, 0.25}, 0.4, -0.2};
    writer.write(odom);
    writer.write(scan);
    writer.write(flaserScan(180));

    rgnav::testing::TempDir dir;
    const std::string path = dir.file("run.log");
    rgnav::testing::writeFile(path, out.str());
    rgnav::CarmenLogReader reader(path);
    const rgnav::testing::LogContents log = rgnav::testing::readAll(reader);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, log.scans.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, log.odometry.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, log.stats.malformedLines);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, log.stats.noReturnRanges);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, log.stats.droppedRanges);

    const LaserScan& back = log.scans.front();
    CPPUNIT_ASSERT_EQUAL(scan.ranges.size(), back.ranges.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(scan.angleIncrement, back.angleIncrement, 1e-12);
    CPPUNIT_ASSERT(std::isinf(back.ranges[0]) && back.ranges[0] > 0.0f);
    CPPUNIT_ASSERT(std::isnan(back.ranges[1]));
    for (std::size_t i = 2; i < scan.ranges.size(); ++i) {
      CPPUNIT_ASSERT_DOUBLES_EQUAL(scan.ranges[i], back.ranges[i], 0.0005 + 1e-6);
    }
    CPPUNIT_ASSERT_DOUBLES_EQUAL(scan.stamp, back.stamp, 1e-6);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(scan.sensorPose.x, back.sensorPose.x, 1e-6);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(scan.sensorPose.y, back.sensorPose.y, 1e-6);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(scan.sensorPose.theta, back.sensorPose.theta, 1e-6);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(scan.odometry.x, back.odometry.x, 1e-6);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(scan.odometry.theta, back.odometry.theta, 1e-6);
    CPPUNIT_ASSERT_EQUAL(std::size_t{180}, log.scans.back().ranges.size());

    const OdometryReading& o = log.odometry.front();
    CPPUNIT_ASSERT_DOUBLES_EQUAL(odom.stamp, o.stamp, 1e-6);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(odom.pose.x, o.pose.x, 1e-6);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(odom.pose.theta, o.pose.theta, 1e-6);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(odom.translationalVelocity, o.translationalVelocity, 1e-6);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(odom.rotationalVelocity, o.rotationalVelocity, 1e-6);
  }

  void writesFixedFormat() {
    std::ostringstream out;
    CarmenLogWriter writer(out, {"sim1", 81.91});
    LaserScan scan = flaserScan(180);
    scan.ranges.assign(180, 2.0f);
    scan.ranges[0] = LaserScan::kNoReturn;
    scan.stamp = 1.5;
    scan.sensorPose = {1.0, 2.0, -0.5};
    writer.write(OdometryReading{0, 0.25, {1.0, 2.0, 0.5}, 0.5, 0.0});
    writer.write(scan);
    const std::string text = out.str();
    CPPUNIT_ASSERT(text.starts_with(
        "ODOM 1.000000 2.000000 0.500000 0.500000 0.000000 0.000000 0.250000 sim1 0.250000\n"
        "FLASER 180 81.910 2.000 2.000 "));
    CPPUNIT_ASSERT(text.ends_with(
        " 2.000 1.000000 2.000000 -0.500000 0.000000 0.000000 0.000000 1.500000 sim1 1.500000\n"));
  }

  void sameSeedGivesByteIdenticalLog() {
    const std::string a = simulatedLog(99);
    CPPUNIT_ASSERT_EQUAL(std::size_t{100}, static_cast<std::size_t>(std::count(a.begin(), a.end(), '\n')));
    CPPUNIT_ASSERT(a == simulatedLog(99));
    CPPUNIT_ASSERT(a != simulatedLog(100));
  }

  void rejectsWhatFlaserCannotExpress() {
    std::ostringstream out;
    CarmenLogWriter writer(out);
    LaserScan narrow = flaserScan(181);
    narrow.startAngle = -M_PI / 4;
    CPPUNIT_ASSERT_THROW(writer.write(narrow), rgnav::InvalidArgumentError);
    LaserScan coarse = flaserScan(180);
    coarse.angleIncrement = 2.0 * coarse.angleIncrement;
    CPPUNIT_ASSERT_THROW(writer.write(coarse), rgnav::InvalidArgumentError);
    LaserScan lost = flaserScan(180);
    lost.sensorPose.x = NAN;
    CPPUNIT_ASSERT_THROW(writer.write(lost), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT(out.str().empty());
    CPPUNIT_ASSERT_THROW(CarmenLogWriter(out, {"two words", 81.91}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(CarmenLogWriter(out, {"", 81.91}), rgnav::InvalidArgumentError);
    std::ostringstream broken;
    broken.setstate(std::ios::badbit);
    CarmenLogWriter failing(broken);
    CPPUNIT_ASSERT_THROW(failing.write(flaserScan(180)), rgnav::FileError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(CarmenLogWriterTest);
