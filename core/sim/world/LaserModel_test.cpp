// Tests the simulated laser: beam layout (181 / 361 beams over 180 degrees), scan fields and
// the laser's mounting offset, Gaussian range noise (mean and standard deviation of the range
// errors within sampling error), the dropout rate, max range, seeding, bad configurations, and
// round obstacles (people): the exact ray-circle distance, and the laser seeing a person.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/sim/world/DiskRaycast.h"
#include "core/sim/world/LaserModel.h"

using namespace rgnav;

namespace {

// A closed 12 x 8 m room: every beam from inside returns within 15 m.
OccupancyGrid room() {
  OccupancyGrid grid(240, 160, 0.05, {0.0, 0.0});
  for (int col = 0; col < 240; ++col) {
    grid.set({col, 0}, Cell::Occupied);
    grid.set({col, 159}, Cell::Occupied);
  }
  for (int row = 0; row < 160; ++row) {
    grid.set({0, row}, Cell::Occupied);
    grid.set({239, row}, Cell::Occupied);
  }
  return grid;
}

LaserConfig halfDegree(double sigma, double dropout) {
  LaserConfig config;
  config.angularResolution = M_PI / 360.0;
  config.rangeNoiseSigma = sigma;
  config.dropoutProbability = dropout;
  config.forwardOffset = 0.2;
  return config;
}

const Pose2D kRobot{4.0, 3.0, 0.3};

}  // namespace

class LaserModelTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LaserModelTest);
  CPPUNIT_TEST(beamLayoutAndScanFields);
  CPPUNIT_TEST(noiseMeanAndSpreadMatchSigma);
  CPPUNIT_TEST(dropoutRateMatchesProbability);
  CPPUNIT_TEST(beyondMaxRangeIsNoReturn);
  CPPUNIT_TEST(sameSeedSameScans);
  CPPUNIT_TEST(badConfigurationsAreRejected);
  CPPUNIT_TEST(rayCircleDistanceIsExact);
  CPPUNIT_TEST(theLaserSeesAPerson);
  CPPUNIT_TEST_SUITE_END();

 public:
  void beamLayoutAndScanFields() {
    CPPUNIT_ASSERT_EQUAL(std::size_t(181), LaserModel(LaserConfig{}).beamCount());
    const LaserModel laser(halfDegree(0.0, 0.0));
    CPPUNIT_ASSERT_EQUAL(std::size_t(361), laser.beamCount());
    const Raycaster raycaster(room());
    std::mt19937_64 rng(1);
    const Pose2D odometry{0.1, -0.2, 0.05};
    const LaserScan scan = laser.simulate(kRobot, odometry, 42, 12.5, raycaster, rng);
    CPPUNIT_ASSERT_EQUAL(DataId(42), scan.id);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(12.5, scan.stamp, 0.0);
    CPPUNIT_ASSERT(scan.odometry == odometry);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.0 + 0.2 * std::cos(0.3), scan.sensorPose.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.0 + 0.2 * std::sin(0.3), scan.sensorPose.y, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.3, scan.sensorPose.theta, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-M_PI / 2, scan.startAngle, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI / 360, scan.angleIncrement, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(30.0, scan.maxRange, 0.0);
    CPPUNIT_ASSERT_EQUAL(std::size_t(361), scan.ranges.size());
    // Without noise the ranges are the raycaster's from the laser pose; the middle beam looks
    // along the heading, the last one to the left.
    const WorldPoint from{scan.sensorPose.x, scan.sensorPose.y};
    CPPUNIT_ASSERT_EQUAL(raycaster.cast(from, 0.3, 30.0), scan.ranges[180]);
    CPPUNIT_ASSERT_EQUAL(raycaster.cast(from, 0.3 + M_PI / 2, 30.0), scan.ranges[360]);
    CPPUNIT_ASSERT_EQUAL(raycaster.cast(from, 0.3 - M_PI / 2, 30.0), scan.ranges[0]);
  }

  void noiseMeanAndSpreadMatchSigma() {
    const double sigma = 0.03;
    const LaserModel laser(halfDegree(sigma, 0.0));
    const Raycaster raycaster(room());
    std::vector<float> truth(laser.beamCount());
    raycaster.scan(laser.laserPose(kRobot), laser.startAngle(), M_PI / 360, 30.0, truth);
    std::mt19937_64 rng(2024);
    double sum = 0.0, sumSquares = 0.0;
    std::size_t n = 0;
    for (int k = 0; k < 300; ++k) {
      const LaserScan scan = laser.simulate(kRobot, kRobot, DataId(k + 1), k * 0.1, raycaster, rng);
      for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
        const double error = double(scan.ranges[i]) - double(truth[i]);
        sum += error;
        sumSquares += error * error;
        ++n;
      }
    }
    const double mean = sum / double(n);
    const double stddev = std::sqrt(sumSquares / double(n) - mean * mean);
    // Four standard errors: of the mean sigma / sqrt(n), of the deviation sigma / sqrt(2 n).
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, mean, 4.0 * sigma / std::sqrt(double(n)));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(sigma, stddev, 4.0 * sigma / std::sqrt(2.0 * double(n)));
  }

  void dropoutRateMatchesProbability() {
    const double p = 0.15;
    const LaserModel laser(halfDegree(0.01, p));
    const Raycaster raycaster(room());
    std::mt19937_64 rng(5);
    std::size_t dropped = 0, n = 0;
    for (int k = 0; k < 200; ++k) {
      const LaserScan scan = laser.simulate(kRobot, kRobot, DataId(k + 1), 0.0, raycaster, rng);
      for (const float r : scan.ranges) {
        dropped += std::isinf(r);
        ++n;
      }
    }
    CPPUNIT_ASSERT_DOUBLES_EQUAL(p, double(dropped) / double(n), 4.0 * std::sqrt(p * (1 - p) / double(n)));
  }

  void beyondMaxRangeIsNoReturn() {
    LaserConfig config = halfDegree(0.05, 0.0);
    config.maxRange = 3.0;
    const LaserModel laser(config);
    const Raycaster raycaster(room());
    std::vector<float> truth(laser.beamCount());
    raycaster.scan(laser.laserPose(kRobot), laser.startAngle(), M_PI / 360, 100.0, truth);
    std::mt19937_64 rng(9);
    const LaserScan scan = laser.simulate(kRobot, kRobot, 1, 0.0, raycaster, rng);
    std::size_t far = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
      CPPUNIT_ASSERT(std::isinf(scan.ranges[i]) || scan.ranges[i] < 3.0f);
      if (truth[i] > 3.3f) {
        CPPUNIT_ASSERT(std::isinf(scan.ranges[i]));
        ++far;
      }
    }
    CPPUNIT_ASSERT(far > 100);
  }

  void sameSeedSameScans() {
    const LaserModel laser(halfDegree(0.02, 0.1));
    const Raycaster raycaster(room());
    std::mt19937_64 a(77), b(77), c(78);
    for (int k = 0; k < 5; ++k) {
      const LaserScan first = laser.simulate(kRobot, kRobot, DataId(k + 1), 0.0, raycaster, a);
      CPPUNIT_ASSERT(first == laser.simulate(kRobot, kRobot, DataId(k + 1), 0.0, raycaster, b));
      CPPUNIT_ASSERT(!(first == laser.simulate(kRobot, kRobot, DataId(k + 1), 0.0, raycaster, c)));
    }
  }

  void badConfigurationsAreRejected() {
    const auto rejected = [](auto edit) {
      LaserConfig config;
      edit(config);
      CPPUNIT_ASSERT_THROW(LaserModel{config}, InvalidArgumentError);
    };
    rejected([](LaserConfig& c) { c.angularResolution = 0.7 * M_PI / 180; });
    rejected([](LaserConfig& c) { c.angularResolution = 0.0; });
    rejected([](LaserConfig& c) { c.fieldOfView = 7.0; });
    rejected([](LaserConfig& c) { c.maxRange = 0.0; });
    rejected([](LaserConfig& c) { c.rangeNoiseSigma = -0.01; });
    rejected([](LaserConfig& c) { c.dropoutProbability = 1.5; });
    rejected([](LaserConfig& c) { c.dropoutProbability = std::nan(""); });
    rejected([](LaserConfig& c) { c.mountingHeight = 0.0; });
  }

  void rayCircleDistanceIsExact() {
    const DiskObstacle person{{3.0, 1.0}, 0.25};
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.75, castToDisk({0.0, 1.0}, 0.0, person), 1e-12);
    // Straight down onto the top of the disk.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.75, castToDisk({3.0, 3.0}, -M_PI / 2.0, person), 1e-12);
    // Off-centre: a beam along y = 1.15 meets the circle at x = 3 - sqrt(0.25^2 - 0.15^2) = 2.8.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.8, castToDisk({0.0, 1.15}, 0.0, person), 1e-12);
    // Grazing (y = 1.25), passing beside, pointing away, and starting inside.
    CPPUNIT_ASSERT(std::isinf(castToDisk({0.0, 1.25}, 0.0, person)));
    CPPUNIT_ASSERT(std::isinf(castToDisk({0.0, 1.3}, 0.0, person)));
    CPPUNIT_ASSERT(std::isinf(castToDisk({0.0, 1.0}, M_PI, person)));
    CPPUNIT_ASSERT_EQUAL(0.0, castToDisk({3.1, 1.0}, 0.7, person));
  }

  void theLaserSeesAPerson() {
    const LaserModel laser(halfDegree(0.0, 0.0));  // 0.2 m ahead of the robot centre
    const Raycaster raycaster(room());
    const Pose2D robot{2.0, 4.0, 0.0};             // laser at (2.2, 4), the wall 9.75 m ahead
    const DiskObstacle person{{5.2, 4.0}, 0.25};
    std::mt19937_64 rng(1);
    const LaserScan without = laser.simulate(robot, robot, 1, 0.0, raycaster, rng);
    const LaserScan with = laser.simulate(robot, robot, 2, 0.0, raycaster, rng, std::span(&person, 1));
    const std::size_t ahead = 180;  // of 361 beams from -90 degrees: straight ahead
    CPPUNIT_ASSERT_DOUBLES_EQUAL(9.75, without.ranges[ahead], 1e-4);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.75, with.ranges[ahead], 1e-4);
    // The person covers asin(0.25 / 3) = 4.78 degrees either side: 9 half-degree beams each way.
    int shortened = 0;
    for (std::size_t i = 0; i < with.ranges.size(); ++i) {
      if (with.ranges[i] < without.ranges[i]) {
        ++shortened;
        CPPUNIT_ASSERT(i >= ahead - 9 && i <= ahead + 9);
        CPPUNIT_ASSERT(with.ranges[i] >= 2.75f - 1e-4f && with.ranges[i] <= 3.0f);
      } else {
        CPPUNIT_ASSERT_EQUAL(without.ranges[i], with.ranges[i]);
      }
    }
    CPPUNIT_ASSERT_EQUAL(19, shortened);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(LaserModelTest);
