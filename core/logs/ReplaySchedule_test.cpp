// Tests ReplaySchedule (release times in scaled real time, the as-fast-as-consumed window) and the
// replay mode text parser and formatter.
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "core/logs/ReplaySchedule.h"

using rgnav::ReplayMode;
using rgnav::ReplaySchedule;

class ReplayScheduleTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ReplayScheduleTest);
  CPPUNIT_TEST(realTimeReleasesAtLogTime);
  CPPUNIT_TEST(speedFactorCompressesTime);
  CPPUNIT_TEST(recordsBeforeTheFirstStampAreDueAtOnce);
  CPPUNIT_TEST(asFastAsConsumedIsLimitedByTheWindow);
  CPPUNIT_TEST(badSchedulesAreRejected);
  CPPUNIT_TEST(modesAreParsed);
  CPPUNIT_TEST(badModesAreConfigErrors);
  CPPUNIT_TEST(formattedModesParseBack);
  CPPUNIT_TEST_SUITE_END();

 public:
  void realTimeReleasesAtLogTime() {
    const ReplaySchedule schedule(ReplayMode{}, 100.0);
    CPPUNIT_ASSERT(schedule.released(100.0, 0.0));
    CPPUNIT_ASSERT(!schedule.released(105.0, 4.99));
    CPPUNIT_ASSERT(schedule.released(105.0, 5.0));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(5.0, schedule.releaseTime(105.0), 1e-12);
    CPPUNIT_ASSERT(schedule.withinWindow(1000000, 0));
  }

  void speedFactorCompressesTime() {
    const ReplaySchedule schedule({ReplayMode::Kind::RealTime, 100.0}, 976052890.0);
    CPPUNIT_ASSERT(!schedule.released(976052990.0, 0.999));
    CPPUNIT_ASSERT(schedule.released(976052990.0, 1.0));
    const ReplaySchedule slow({ReplayMode::Kind::RealTime, 0.5}, 0.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.0, slow.releaseTime(2.0), 1e-12);
  }

  void recordsBeforeTheFirstStampAreDueAtOnce() {
    const ReplaySchedule schedule(ReplayMode{}, 100.0);
    CPPUNIT_ASSERT_EQUAL(0.0, schedule.releaseTime(99.5));
    CPPUNIT_ASSERT(schedule.released(99.5, 0.0));
  }

  void asFastAsConsumedIsLimitedByTheWindow() {
    const ReplaySchedule schedule({ReplayMode::Kind::AsFastAsConsumed, 1.0}, 0.0, 10);
    CPPUNIT_ASSERT(schedule.released(1e9, 0.0));
    CPPUNIT_ASSERT_EQUAL(0.0, schedule.releaseTime(1e9));
    CPPUNIT_ASSERT(schedule.withinWindow(0, 0));
    CPPUNIT_ASSERT(schedule.withinWindow(9, 0));
    CPPUNIT_ASSERT(!schedule.withinWindow(10, 0));
    CPPUNIT_ASSERT(schedule.withinWindow(10, 1));
  }

  void badSchedulesAreRejected() {
    CPPUNIT_ASSERT_THROW(ReplaySchedule({ReplayMode::Kind::RealTime, 0.0}, 0.0),
                         rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(ReplaySchedule({ReplayMode::Kind::RealTime, -2.0}, 0.0),
                         rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(ReplaySchedule(ReplayMode{}, 0.0, 0), rgnav::InvalidArgumentError);
  }

  void modesAreParsed() {
    const ReplayMode asFast{ReplayMode::Kind::AsFastAsConsumed, 1.0};
    CPPUNIT_ASSERT(ReplayMode{} == rgnav::parseReplayMode("realtime"));
    CPPUNIT_ASSERT(ReplayMode({ReplayMode::Kind::RealTime, 100.0}) ==
                   rgnav::parseReplayMode("x100"));
    CPPUNIT_ASSERT(ReplayMode({ReplayMode::Kind::RealTime, 100.0}) ==
                   rgnav::parseReplayMode("100"));
    CPPUNIT_ASSERT(ReplayMode({ReplayMode::Kind::RealTime, 0.5}) ==
                   rgnav::parseReplayMode("X0.5"));
    CPPUNIT_ASSERT(asFast == rgnav::parseReplayMode("max"));
    CPPUNIT_ASSERT(asFast == rgnav::parseReplayMode("asfast"));
    CPPUNIT_ASSERT(asFast == rgnav::parseReplayMode("MAX"));
  }

  void badModesAreConfigErrors() {
    for (const char* text : {"", "x", "fast", "x0", "0", "-3", "x-1", "nan", "xinf", "x100abc",
                             " x100", "realtime2", "1e999"}) {
      CPPUNIT_ASSERT_THROW_MESSAGE(text, rgnav::parseReplayMode(text), rgnav::ConfigError);
    }
  }

  void formattedModesParseBack() {
    for (const ReplayMode& mode :
         {ReplayMode{}, ReplayMode{ReplayMode::Kind::RealTime, 100.0},
          ReplayMode{ReplayMode::Kind::RealTime, 2.5},
          ReplayMode{ReplayMode::Kind::AsFastAsConsumed, 1.0}}) {
      CPPUNIT_ASSERT(mode == rgnav::parseReplayMode(rgnav::formatReplayMode(mode)));
    }
    CPPUNIT_ASSERT_EQUAL(std::string("realtime"), rgnav::formatReplayMode(ReplayMode{}));
    CPPUNIT_ASSERT_EQUAL(std::string("x100"),
                         rgnav::formatReplayMode({ReplayMode::Kind::RealTime, 100.0}));
    CPPUNIT_ASSERT_EQUAL(std::string("asfast"),
                         rgnav::formatReplayMode({ReplayMode::Kind::AsFastAsConsumed, 1.0}));
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(ReplayScheduleTest);
