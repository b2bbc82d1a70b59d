// Tests which pose revisions the ScanMapper module may forget: the lowest revision that the
// active followers have applied, anonymous callers and idle followers not counted.
#include <cppunit/extensions/HelperMacros.h>

#include "servers/scanmapper/RevisionFollowers.h"

using rgnav::RevisionFollowers;

class RevisionFollowersTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RevisionFollowersTest);
  CPPUNIT_TEST(noFollowerForgetsNothing);
  CPPUNIT_TEST(theSlowestActiveFollowerCounts);
  CPPUNIT_TEST(aRestartedFollowerHoldsWhatItNeedsAgain);
  CPPUNIT_TEST_SUITE_END();

 public:
  void noFollowerForgetsNothing() {
    RevisionFollowers followers;
    CPPUNIT_ASSERT(!followers.appliedByAll(0.0));
    followers.asked("", 9, 0.0);  // anonymous: holds nothing, frees nothing
    CPPUNIT_ASSERT(!followers.appliedByAll(1.0));
  }
  void theSlowestActiveFollowerCounts() {
    RevisionFollowers followers;
    followers.asked("RGMappingKernel", 7, 0.0);
    followers.asked("Viewer", 3, 10.0);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{3}, followers.appliedByAll(20.0).value());
    // The viewer went away: after the idle time only the kernel, which goes on asking, counts;
    // once it stops too, no one.
    followers.asked("RGMappingKernel", 8, 50.0);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{8}, followers.appliedByAll(10.0 + RevisionFollowers::kIdleSeconds).value());
    CPPUNIT_ASSERT(!followers.appliedByAll(50.0 + RevisionFollowers::kIdleSeconds));
  }
  void aRestartedFollowerHoldsWhatItNeedsAgain() {
    RevisionFollowers followers;
    followers.asked("RGMappingKernel", 12, 0.0);
    followers.asked("RGMappingKernel", 10, 5.0);  // restarted from its checkpoint
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{10}, followers.appliedByAll(6.0).value());
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(RevisionFollowersTest);
