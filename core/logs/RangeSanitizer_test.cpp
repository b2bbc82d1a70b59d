// Tests the REP-117 range conversion: kept, dropped (NaN) and no-return (+inf) beams and counts.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/logs/RangeSanitizer.h"

using rgnav::LogStats;

class RangeSanitizerTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RangeSanitizerTest);
  CPPUNIT_TEST(measurementsAreKept);
  CPPUNIT_TEST(invalidValuesAreDropped);
  CPPUNIT_TEST(maxRangeAndBeyondMeanNoReturn);
  CPPUNIT_TEST(wholeScanIsConvertedAndCounted);
  CPPUNIT_TEST_SUITE_END();

 public:
  void measurementsAreKept() {
    LogStats stats;
    CPPUNIT_ASSERT_EQUAL(0.0f, rgnav::sanitizeRange(0.0, 80.0, stats));
    CPPUNIT_ASSERT_EQUAL(79.99f, rgnav::sanitizeRange(79.99, 80.0, stats));
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, stats.droppedRanges + stats.noReturnRanges);
  }

  void invalidValuesAreDropped() {
    LogStats stats;
    constexpr double kInf = std::numeric_limits<double>::infinity();
    for (const double raw : {std::nan(""), kInf, -kInf, -0.01}) {
      CPPUNIT_ASSERT(std::isnan(rgnav::sanitizeRange(raw, 80.0, stats)));
    }
    CPPUNIT_ASSERT_EQUAL(std::size_t{4}, stats.droppedRanges);
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, stats.noReturnRanges);
  }

  void maxRangeAndBeyondMeanNoReturn() {
    LogStats stats;
    for (const double raw : {80.0, 81.83, 81.91}) {
      const float range = rgnav::sanitizeRange(raw, 80.0, stats);
      CPPUNIT_ASSERT(std::isinf(range) && range > 0);
    }
    CPPUNIT_ASSERT_EQUAL(std::size_t{3}, stats.noReturnRanges);
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, stats.droppedRanges);
  }

  void wholeScanIsConvertedAndCounted() {
    LogStats stats;
    const std::vector<double> raw = {1.5, -1.0, 50.0, 3.25};
    std::vector<float> ranges = {9.0f};
    rgnav::sanitizeRanges(raw, 50.0, ranges, stats);
    CPPUNIT_ASSERT_EQUAL(std::size_t{4}, ranges.size());
    CPPUNIT_ASSERT_EQUAL(1.5f, ranges[0]);
    CPPUNIT_ASSERT(std::isnan(ranges[1]));
    CPPUNIT_ASSERT(std::isinf(ranges[2]));
    CPPUNIT_ASSERT_EQUAL(3.25f, ranges[3]);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, stats.droppedRanges);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, stats.noReturnRanges);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(RangeSanitizerTest);
