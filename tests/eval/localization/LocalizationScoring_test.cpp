// Tests the scoring parts of the localization evaluation: corrected poses matched to scans by
// stamp (nearest within the tolerance, with an offset, unmatched scans left out) and the error
// summary (mean, nearest-rank 95th percentile, rotation wrapped, lost scans over the bound).
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <vector>

#include "tests/eval/localization/LocalizationErrors.h"
#include "tests/eval/localization/StampedPoses.h"

namespace {

rgnav::LaserScan scanAt(double stamp) {
  rgnav::LaserScan scan;
  scan.stamp = stamp;
  return scan;
}

}  // namespace

class LocalizationScoringTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LocalizationScoringTest);
  CPPUNIT_TEST(matchesTheNearestStampWithinTheTolerance);
  CPPUNIT_TEST(appliesTheStampOffset);
  CPPUNIT_TEST(summarisesMeanPercentileRotationAndLost);
  CPPUNIT_TEST_SUITE_END();

 public:
  void matchesTheNearestStampWithinTheTolerance() {
    const std::vector<rgnav::StampedPose> poses{{10.0, {1, 0, 0}}, {10.0015, {2, 0, 0}}, {11.0, {3, 0, 0}}};
    const std::vector<rgnav::LaserScan> scans{scanAt(10.0009), scanAt(10.9995), scanAt(10.5), scanAt(9.0)};
    const rgnav::PoseMatch match = rgnav::matchByStamp(scans, poses, 0.0, 0.001);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, match.matched);
    CPPUNIT_ASSERT(match.poses[0] && match.poses[0]->x == 2.0);  // 0.6 ms from the second, 0.9 ms from the first
    CPPUNIT_ASSERT(match.poses[1] && match.poses[1]->x == 3.0);
    CPPUNIT_ASSERT(!match.poses[2]);
    CPPUNIT_ASSERT(!match.poses[3]);
  }

  void appliesTheStampOffset() {
    const std::vector<rgnav::StampedPose> poses{{0.5, {7, 0, 0}}};
    const std::vector<rgnav::LaserScan> scans{scanAt(100.5)};
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, rgnav::matchByStamp(scans, poses, 0.0, 0.001).matched);
    const rgnav::PoseMatch match = rgnav::matchByStamp(scans, poses, 100.0, 0.001);
    CPPUNIT_ASSERT(match.poses[0] && match.poses[0]->x == 7.0);
  }

  void summarisesMeanPercentileRotationAndLost() {
    std::vector<rgnav::PoseError> errors;
    for (int i = 1; i <= 20; ++i) errors.push_back(rgnav::poseError({0.1 * i, 0, 0}, {0, 0, 0}));
    errors.push_back(rgnav::poseError({0, 0, M_PI - 0.01}, {0, 0, -M_PI + 0.01}));
    const rgnav::ErrorSummary s = rgnav::summarize(errors, 1.0);
    CPPUNIT_ASSERT_EQUAL(std::size_t{21}, s.scans);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(21.0 / 21.0, s.translationMeanM, 1e-9);  // (0.1 + ... + 2.0) / 21
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.9, s.translationP95M, 1e-9);           // rank ceil(0.95 * 21) = 20 of 21
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.02 / 21.0 * 180.0 / M_PI, s.rotationMeanDeg, 1e-9);
    CPPUNIT_ASSERT_EQUAL(std::size_t{10}, s.lost);  // 1.1 .. 2.0
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(LocalizationScoringTest);
