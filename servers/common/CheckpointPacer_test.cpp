// Tests CheckpointPacer on a clock the test sets: the first checkpoint is due at once, the next
// one after the interval, and after a slow write only when writing took at most the allowed
// share of the time since; bad settings are refused.
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "servers/common/CheckpointPacer.h"
#include "tests/support/ManualClock.h"

using namespace rgnav;
using std::chrono::milliseconds;
using testing::ManualClock;

class CheckpointPacerTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CheckpointPacerTest);
  CPPUNIT_TEST(quickWritesFollowTheInterval);
  CPPUNIT_TEST(slowWritesTakeAtMostTheirShare);
  CPPUNIT_TEST(badSettingsAreRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void quickWritesFollowTheInterval() {
    const ManualClock t;
    CheckpointPacer pacer(1.0, 0.1, t.clock());
    CPPUNIT_ASSERT(pacer.due());
    const auto began = pacer.now();
    t.advance(milliseconds(20));
    pacer.written(began);
    t.advance(milliseconds(999));
    CPPUNIT_ASSERT(!pacer.due());
    t.advance(milliseconds(1));
    CPPUNIT_ASSERT(pacer.due());
  }

  void slowWritesTakeAtMostTheirShare() {
    const ManualClock t;
    CheckpointPacer pacer(1.0, 0.1, t.clock());
    const auto began = pacer.now();
    t.advance(milliseconds(500));  // a large state: half a second to write
    pacer.written(began);
    t.advance(milliseconds(4499));
    CPPUNIT_ASSERT(!pacer.due());
    t.advance(milliseconds(1));  // 0.5 s of writing in 5 s
    CPPUNIT_ASSERT(pacer.due());
    // A quick write again: back to the interval.
    const auto again = pacer.now();
    t.advance(milliseconds(10));
    pacer.written(again);
    t.advance(milliseconds(1000));
    CPPUNIT_ASSERT(pacer.due());
  }

  void badSettingsAreRefused() {
    CPPUNIT_ASSERT_THROW(CheckpointPacer(-1.0), ConfigError);
    CPPUNIT_ASSERT_THROW(CheckpointPacer(1.0, 0.0), ConfigError);
    CPPUNIT_ASSERT_THROW(CheckpointPacer(1.0, 1.5), ConfigError);
    CPPUNIT_ASSERT_NO_THROW(CheckpointPacer(0.0, 1.0));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(CheckpointPacerTest);
