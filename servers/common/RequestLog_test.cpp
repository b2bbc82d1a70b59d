// Tests RequestLog: a recorded request keeps its first answer, and only the latest requests up
// to the bound are kept.
#include <cppunit/extensions/HelperMacros.h>

#include "servers/common/RequestLog.h"

using rgnav::RequestLog;

class RequestLogTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RequestLogTest);
  CPPUNIT_TEST(aRepeatedRequestGetsTheFirstAnswer);
  CPPUNIT_TEST(onlyTheLatestRequestsAreKept);
  CPPUNIT_TEST_SUITE_END();

 public:
  void aRepeatedRequestGetsTheFirstAnswer() {
    RequestLog log;
    CPPUNIT_ASSERT(!log.answered(77));
    log.record(77, 5);
    log.record(77, 9);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{5}, log.answered(77).value());
  }

  void onlyTheLatestRequestsAreKept() {
    RequestLog log(3);
    for (std::uint64_t id = 1; id <= 5; ++id) log.record(id, id * 10);
    CPPUNIT_ASSERT_EQUAL(std::size_t{3}, log.size());
    CPPUNIT_ASSERT(!log.answered(2));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{30}, log.answered(3).value());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{50}, log.answered(5).value());
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RequestLogTest);
