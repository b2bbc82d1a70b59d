// Tests which pose revisions the ScanMapper module may forget: the lowest revision that the
// active followers have applied; anonymous and unknown callers change nothing, idle followers are
// not counted and are forgotten.
#include <cppunit/extensions/HelperMacros.h>

#include "servers/scanmapper/RevisionFollowers.h"

using rgnav::RevisionFollowers;

class RevisionFollowersTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RevisionFollowersTest);
  CPPUNIT_TEST(noFollowerForgetsNothing);
  CPPUNIT_TEST(theSlowestActiveFollowerCounts);
  CPPUNIT_TEST(aRestartedFollowerHoldsWhatItNeedsAgain);
  CPPUNIT_TEST(unknownCallersChangeNothing);
  CPPUNIT_TEST_SUITE_END();

 public:
  void noFollowerForgetsNothing() {
    RevisionFollowers followers({"RGMappingKernel"});
    CPPUNIT_ASSERT(!followers.appliedByAll(0.0));
    followers.asked("", 9, 0.0);  // anonymous: holds nothing, frees nothing
    CPPUNIT_ASSERT(!followers.appliedByAll(1.0));
  }
  void theSlowestActiveFollowerCounts() {
    RevisionFollowers followers({"RGMappingKernel", "Viewer"});
    followers.asked("RGMappingKernel", 7, 0.0);
    followers.asked("Viewer", 3, 10.0);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{3}, followers.appliedByAll(20.0).value());
    // The viewer went away: after the idle time only the kernel, which goes on asking, counts;
    // once it stops too, no one.
    followers.asked("RGMappingKernel", 8, 50.0);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{8}, followers.appliedByAll(10.0 + RevisionFollowers::kIdleSeconds).value());
    CPPUNIT_ASSERT(!followers.appliedByAll(50.0 + RevisionFollowers::kIdleSeconds));
    followers.asked("RGMappingKernel", 9, 10.0 + RevisionFollowers::kIdleSeconds);  // the viewer is forgotten
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, followers.size());
  }
  void unknownCallersChangeNothing() {
    RevisionFollowers followers({"RGMappingKernel"});
    followers.asked("RGMappingKernel", 5, 0.0);
    // A stranger claiming every revision applied neither frees nor holds anything.
    followers.asked("stranger", ~std::uint64_t{0}, 1.0);
    followers.asked("another", 0, 1.0);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{5}, followers.appliedByAll(2.0).value());
    for (int i = 0; i < 1000; ++i) followers.asked("name-" + std::to_string(i), 0, 3.0);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, followers.size());
  }
  void aRestartedFollowerHoldsWhatItNeedsAgain() {
    RevisionFollowers followers({"RGMappingKernel"});
    followers.asked("RGMappingKernel", 12, 0.0);
    followers.asked("RGMappingKernel", 10, 5.0);  // restarted from its checkpoint
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{10}, followers.appliedByAll(6.0).value());
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(RevisionFollowersTest);
