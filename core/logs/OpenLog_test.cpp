// Tests readLaserScans (OpenLog.h): a log's scans in order, the first N of them, and a log
// without scans refused.
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "core/logs/LogTestFiles.h"
#include "core/logs/OpenLog.h"

using rgnav::testing::TempDir;

namespace {

constexpr const char* kOdom = "ODOM 0 0 0 0 0 0 1.0 host 1.0\n";

std::string flaser(double x, double stamp) {
  return "FLASER 3 1.0 2.0 3.0 " + std::to_string(x) + " 0 0 " + std::to_string(x) + " 0 0 " + std::to_string(stamp) +
         " host " + std::to_string(stamp) + "\n";
}

}  // namespace

class OpenLogTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(OpenLogTest);
  CPPUNIT_TEST(readsTheScansInOrderUpToTheLimit);
  CPPUNIT_TEST(refusesALogWithoutScans);
  CPPUNIT_TEST_SUITE_END();

 public:
  void readsTheScansInOrderUpToTheLimit() {
    TempDir dir;
    const std::string path = dir.file("three.log");
    rgnav::testing::writeFile(path, std::string(kOdom) + flaser(1.0, 2.0) + kOdom + flaser(2.0, 3.0) + flaser(3.0, 4.0));
    const auto all = rgnav::readLaserScans(path);
    CPPUNIT_ASSERT_EQUAL(std::size_t{3}, all.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, all[0].sensorPose.x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.0, all[2].sensorPose.x, 1e-9);
    const auto two = rgnav::readLaserScans(path, {}, 2);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, two.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, two[1].sensorPose.x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.0, two[1].stamp, 1e-9);
  }

  void refusesALogWithoutScans() {
    TempDir dir;
    const std::string path = dir.file("odometry.log");
    rgnav::testing::writeFile(path, std::string(kOdom) + kOdom);
    CPPUNIT_ASSERT_THROW(rgnav::readLaserScans(path), rgnav::InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(OpenLogTest);
