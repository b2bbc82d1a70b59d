// The control loop's period statistics (LoopPeriods.h): the last period, the 99th percentile that
// one slow tick in a hundred does not move but two do, and a window that forgets old ticks.
#include <cppunit/extensions/HelperMacros.h>

#include "servers/lowleveldrive/LoopPeriods.h"

using namespace rgnav;
using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

namespace {

// Ticks `periods` (ms) apart, after a first tick at `t`; returns the last tick's time.
Clock::time_point tickEvery(LoopPeriods& loop, Clock::time_point t, const std::vector<int>& periods) {
  for (int ms : periods) {
    t += milliseconds(ms);
    loop.tickStarted(t);
  }
  return t;
}

}  // namespace

class LoopPeriodsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LoopPeriodsTest);
  CPPUNIT_TEST(nothingBeforeTheSecondTick);
  CPPUNIT_TEST(lastAndPercentile);
  CPPUNIT_TEST(windowForgetsOldTicks);
  CPPUNIT_TEST_SUITE_END();

 public:
  void nothingBeforeTheSecondTick() {
    LoopPeriods loop;
    loop.tickStarted(Clock::time_point{});
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), loop.periods());
    CPPUNIT_ASSERT_EQUAL(0.0, loop.lastSeconds());
    CPPUNIT_ASSERT_EQUAL(0.0, loop.p99Seconds());
  }

  void lastAndPercentile() {
    LoopPeriods loop;
    Clock::time_point t{};
    loop.tickStarted(t);
    std::vector<int> periods(199, 50);
    periods[40] = 90;  // one slow tick in 199: the 99th percentile stays at the period
    t = tickEvery(loop, t, periods);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(199), loop.periods());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.050, loop.p99Seconds(), 1e-9);
    tickEvery(loop, t, {80, 81});  // three slow ones in 201: it does not
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.081, loop.lastSeconds(), 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.080, loop.p99Seconds(), 1e-9);
  }

  void windowForgetsOldTicks() {
    LoopPeriods loop(10);
    Clock::time_point t{};
    loop.tickStarted(t);
    t = tickEvery(loop, t, std::vector<int>(10, 200));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.200, loop.p99Seconds(), 1e-9);
    tickEvery(loop, t, std::vector<int>(10, 50));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.050, loop.p99Seconds(), 1e-9);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(20), loop.periods());
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(LoopPeriodsTest);
