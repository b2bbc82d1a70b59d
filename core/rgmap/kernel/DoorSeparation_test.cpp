// Tests DoorSeparation and the kernel's rule built on it: doors in walls separate their sides; a
// "door" between a wall and a pillar the robot drove around does not, and the kernel keeps its
// two sides one region; without scans a door separates; bad sizes are refused.
#include "core/rgmap/kernel/DoorSeparation.h"

#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "core/rgmap/kernel/testing/SyntheticTour.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {

// A room 8 x 6 m (corner at the origin) with a pillar 0.4 x 0.4 m at (1.5, 3), and door 31
// reported across the 1.3 m gap between the west wall and the pillar.
TourWorld roomWithPillar() {
  TourWorld w;
  w.walls = boxWalls({4, 3}, 0.0, 8, 6);
  for (const Wall& side : boxWalls({1.5, 3}, 0.0, 0.4, 0.4)) w.walls.push_back(side);
  w.doors = {{DetectorGatewayId{31}, {0, 3}, {1.3, 3}, DoorReports::All}};
  return w;
}

// North through the gap and back south around the pillar's east side.
RgMappingKernel pillarTourMap() {
  SyntheticTour tour(roomWithPillar(), kTourDrift);
  tour.driveThrough({{0.65, 1}, {0.65, 5}, {3, 5}, {3, 1}});
  return mapped(tour.inputs(), tour.inputs().size());
}

}  // namespace

class DoorSeparationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(DoorSeparationTest);
  CPPUNIT_TEST(doorsInWallsSeparate);
  CPPUNIT_TEST(gapBesideAPillarDoesNotSeparate);
  CPPUNIT_TEST(kernelKeepsBothSidesOfTheGapOneRegion);
  CPPUNIT_TEST(withoutScansADoorSeparates);
  CPPUNIT_TEST(badSizesAreRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void doorsInWallsSeparate() {
    const std::vector<KernelInput> inputs = twoRoomTour().inputs();
    const RgMappingKernel kernel = mapped(inputs, inputs.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), kernel.state().gateways.size());
    for (const auto& [id, gateway] : kernel.state().gateways) {
      CPPUNIT_ASSERT(separatesSpace(kernel.state(), id, {}));
      CPPUNIT_ASSERT(!gateway.neutralised);
    }
  }

  void gapBesideAPillarDoesNotSeparate() {
    const RgMappingKernel kernel = pillarTourMap();
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), kernel.state().gateways.size());
    CPPUNIT_ASSERT(!separatesSpace(kernel.state(), kernel.state().gateways.begin()->first, {}));
  }

  void kernelKeepsBothSidesOfTheGapOneRegion() {
    const RgMappingKernel kernel = pillarTourMap();
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), kernel.state().regions.size());
    const Gateway& gap = kernel.state().gateways.begin()->second;
    CPPUNIT_ASSERT(gap.neutralised);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), gap.traversalsFrom[kSideA] + gap.traversalsFrom[kSideB]);
    CPPUNIT_ASSERT(kernel.checkConsistency().empty());
  }

  void withoutScansADoorSeparates() {
    RgMapState state = pillarTourMap().state();
    state.scans.clear();
    CPPUNIT_ASSERT(separatesSpace(state, state.gateways.begin()->first, {}));
  }

  void badSizesAreRefused() {
    for (double DoorSeparationConfig::*size :
         {&DoorSeparationConfig::cellSizeM, &DoorSeparationConfig::radiusM, &DoorSeparationConfig::scanMarginM,
          &DoorSeparationConfig::slabHalfDepthM, &DoorSeparationConfig::overhangM,
          &DoorSeparationConfig::seedOffsetM}) {
      DoorSeparationConfig config;
      config.*size = 0.0;
      CPPUNIT_ASSERT_THROW(validate(config), ConfigError);
      config.*size = std::nan("");
      CPPUNIT_ASSERT_THROW(validate(config), ConfigError);
      RgMappingKernelConfig kernel;
      kernel.separation = config;
      CPPUNIT_ASSERT_THROW(RgMappingKernel{kernel}, ConfigError);
    }
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(DoorSeparationTest);
