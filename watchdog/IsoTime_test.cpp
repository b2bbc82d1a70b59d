// Tests ISO-8601 UTC formatting with milliseconds.
#include <cppunit/extensions/HelperMacros.h>

#include "watchdog/IsoTime.h"

using namespace std::chrono;

class IsoTimeTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(IsoTimeTest);
  CPPUNIT_TEST(formatsDateTimeAndMilliseconds);
  CPPUNIT_TEST(truncatesBelowMilliseconds);
  CPPUNIT_TEST_SUITE_END();

 public:
  void formatsDateTimeAndMilliseconds() {
    const system_clock::time_point t = sys_days{year{2024} / 2 / 29} + 23h + 4min + 5s + 67ms;
    CPPUNIT_ASSERT_EQUAL(std::string("2024-02-29T23:04:05.067Z"), rgnav::formatIsoUtcMillis(t));
    CPPUNIT_ASSERT_EQUAL(std::string("1970-01-01T00:00:00.000Z"), rgnav::formatIsoUtcMillis(system_clock::time_point{}));
  }
  void truncatesBelowMilliseconds() {
    const system_clock::time_point t = sys_days{year{2001} / 12 / 31} + 59s + 999999us;
    CPPUNIT_ASSERT_EQUAL(std::string("2001-12-31T00:00:59.999Z"), rgnav::formatIsoUtcMillis(t));
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(IsoTimeTest);
