// Tests whose motion made a contact: driving at a person is the robot's; a standing robot, one
// driving away or passing sideways is walked into; a round robot turning on the spot drives into
// nobody, while a rectangle's corner swinging into a person does.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/sim/people/ContactBlame.h"

using namespace rgnav;

namespace {
const Footprint kDisk = Footprint::disk(0.25);
const Footprint kBox = Footprint::rectangle(0.5, 0.4);  // x -0.25..0.25, y -0.2..0.2 at heading 0
}  // namespace

class ContactBlameTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ContactBlameTest);
  CPPUNIT_TEST(drivingAtAPersonIsTheRobots);
  CPPUNIT_TEST(standingDrivingAwayOrPassingIsWalkedInto);
  CPPUNIT_TEST(turningOnTheSpotDependsOnTheOutline);
  CPPUNIT_TEST_SUITE_END();

 public:
  void drivingAtAPersonIsTheRobots() {
    CPPUNIT_ASSERT(robotDroveInto(kDisk, {0.0, 0.0, 0.0}, 0.5, 0.0, {0.5, 0.0}));
    CPPUNIT_ASSERT(robotDroveInto(kDisk, {0.0, 0.0, 0.0}, 0.5, 0.0, {0.4, 0.3}));     // ahead, to the left
    CPPUNIT_ASSERT(robotDroveInto(kDisk, {0.0, 0.0, M_PI}, -0.5, 0.0, {0.5, 0.0}));  // backing into it
  }

  void standingDrivingAwayOrPassingIsWalkedInto() {
    CPPUNIT_ASSERT(!robotDroveInto(kDisk, {0.0, 0.0, 0.0}, 0.0, 0.0, {0.5, 0.0}));
    CPPUNIT_ASSERT(!robotDroveInto(kDisk, {0.0, 0.0, 0.0}, 0.5, 0.0, {-0.5, 0.0}));  // from behind
    CPPUNIT_ASSERT(!robotDroveInto(kDisk, {0.0, 0.0, 0.0}, 0.5, 0.0, {0.0, 0.5}));   // from the side
    CPPUNIT_ASSERT(!robotDroveInto(kBox, {0.0, 0.0, 0.0}, 0.5, 0.0, {0.0, 0.45}));
  }

  void turningOnTheSpotDependsOnTheOutline() {
    CPPUNIT_ASSERT(!robotDroveInto(kDisk, {0.0, 0.0, 0.0}, 0.0, 1.0, {0.4, 0.4}));
    CPPUNIT_ASSERT(!robotDroveInto(kDisk, {0.0, 0.0, 0.0}, 0.0, -1.0, {0.4, 0.4}));
    // A person off the front-left corner (0.25, 0.2): turning left swings the corner to (-0.2,
    // 0.25) per radian, towards a person ahead-left above it; turning right swings it away.
    CPPUNIT_ASSERT(robotDroveInto(kBox, {0.0, 0.0, 0.0}, 0.0, 1.0, {0.3, 0.45}));
    CPPUNIT_ASSERT(!robotDroveInto(kBox, {0.0, 0.0, 0.0}, 0.0, -1.0, {0.3, 0.45}));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ContactBlameTest);
