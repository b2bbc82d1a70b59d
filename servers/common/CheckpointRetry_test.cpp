// Tests CheckpointRetry and ModuleHealth's DEGRADED state on a clock the test sets: a failed
// checkpoint degrades a running module with the reason and counts it, the next attempt waits a
// backoff that doubles up to its bound, and the first success makes the module healthy again.
#include <cppunit/extensions/HelperMacros.h>

#include "servers/common/CheckpointRetry.h"
#include "tests/support/ManualClock.h"

using namespace rgnav;
using std::chrono::milliseconds;
using testing::ManualClock;

class CheckpointRetryTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CheckpointRetryTest);
  CPPUNIT_TEST(aFailureDegradesTheModuleWithItsReason);
  CPPUNIT_TEST(theBackoffDoublesUpToItsBound);
  CPPUNIT_TEST(aSuccessMakesTheModuleHealthyAgain);
  CPPUNIT_TEST(aDegradingErrorOutranksANewerPlainOne);
  CPPUNIT_TEST_SUITE_END();

 public:
  void aFailureDegradesTheModuleWithItsReason() {
    ModuleHealth health;
    health.setState(ModuleRunState::Running);
    const ManualClock t;
    CheckpointRetry retry(health, milliseconds(100), milliseconds(1000), t.clock());
    CPPUNIT_ASSERT(retry.due());
    retry.failed("state/map: cannot create a temporary file beside it: Read-only file system");
    const ModuleStatusInfo s = health.snapshot();
    CPPUNIT_ASSERT(s.state == ModuleRunState::Degraded);
    CPPUNIT_ASSERT_EQUAL(std::string("checkpoint: state/map: cannot create a temporary file beside it: "
                                     "Read-only file system"),
                         s.lastError);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{1}, s.counters.at("checkpoint_failures"));
  }

  void theBackoffDoublesUpToItsBound() {
    ModuleHealth health;
    const ManualClock t;
    CheckpointRetry retry(health, milliseconds(100), milliseconds(300), t.clock());
    for (const int delay : {100, 200, 300, 300}) {
      retry.failed("disk full");
      CPPUNIT_ASSERT(retry.failing());
      t.advance(milliseconds(delay - 1));
      CPPUNIT_ASSERT(!retry.due());
      t.advance(milliseconds(1));
      CPPUNIT_ASSERT(retry.due());
    }
  }

  void aSuccessMakesTheModuleHealthyAgain() {
    ModuleHealth health;
    health.setState(ModuleRunState::Running);
    const ManualClock t;
    CheckpointRetry retry(health, milliseconds(100), milliseconds(1000), t.clock());
    retry.failed("disk full");
    retry.failed("disk full");
    t.advance(milliseconds(200));
    retry.succeeded();
    CPPUNIT_ASSERT(!retry.failing());
    const ModuleStatusInfo s = health.snapshot();
    CPPUNIT_ASSERT(s.state == ModuleRunState::Running);
    CPPUNIT_ASSERT(s.lastError.empty());
    retry.failed("disk full");  // the backoff starts again from its least
    t.advance(milliseconds(100));
    CPPUNIT_ASSERT(retry.due());
  }

  void aDegradingErrorOutranksANewerPlainOne() {
    ModuleHealth health;
    health.setState(ModuleRunState::Running);
    health.setDegraded("checkpoint", "disk full");
    health.setError("inputs", "ScanMapper restarting");
    CPPUNIT_ASSERT_EQUAL(std::string("checkpoint: disk full"), health.snapshot().lastError);
    health.clearError("checkpoint");
    const ModuleStatusInfo s = health.snapshot();
    CPPUNIT_ASSERT(s.state == ModuleRunState::Running);
    CPPUNIT_ASSERT_EQUAL(std::string("inputs: ScanMapper restarting"), s.lastError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(CheckpointRetryTest);
