// Round trips of the Watchdog.idl conversions for every process state.
#include <cppunit/extensions/HelperMacros.h>

#include "clientlibs/watchdog/convert.h"

using namespace rgnav;

class WatchdogConvertTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(WatchdogConvertTest);
  CPPUNIT_TEST(moduleInfoRoundTripForEveryState);
  CPPUNIT_TEST(eventRoundTrip);
  CPPUNIT_TEST_SUITE_END();

 public:
  void moduleInfoRoundTripForEveryState() {
    for (auto state : {ProcessState::Stopped, ProcessState::Starting, ProcessState::Running, ProcessState::Hung,
                       ProcessState::Backoff, ProcessState::Fatal}) {
      const ModuleProcessInfo info{"LogPlayback", state, 4242, 12.5, 7, "restarted after SIGKILL"};
      CPPUNIT_ASSERT(fromIdl(toIdl(info)) == info);
    }
  }
  void eventRoundTrip() {
    const SupervisionEvent event{17, "2026-11-21T08:00:00.123Z", "LogPlayback", "exited", "signal 9"};
    CPPUNIT_ASSERT(fromIdl(toIdl(event)) == event);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(WatchdogConvertTest);
