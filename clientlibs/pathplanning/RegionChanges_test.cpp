// Which regions the PathPlanning module fetches again after RG map events (RegionChanges.h).
#include <cppunit/extensions/HelperMacros.h>

#include "clientlibs/pathplanning/RegionChanges.h"

using namespace rgnav;

class RegionChangesTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RegionChangesTest);
  CPPUNIT_TEST(namedRegionsOnly);
  CPPUNIT_TEST(costsAndGatewaysChangeNoRegion);
  CPPUNIT_TEST(revisedPosesChangeAll);
  CPPUNIT_TEST_SUITE_END();

  static RgMapEvent event(RgMapEventKind kind, std::uint64_t region, std::uint64_t other = 0, std::uint64_t gateway = 0) {
    return {1, kind, RegionId(region), RegionId(other), GatewayId(gateway), 10};
  }

 public:
  void namedRegionsOnly() {
    const RegionChanges c = regionChanges({event(RgMapEventKind::RegionsMerged, 2, 5),
                                           event(RgMapEventKind::ObjectNamed, 3)});
    CPPUNIT_ASSERT(!c.all);
    CPPUNIT_ASSERT(c.contains(RegionId(2)) && c.contains(RegionId(5)) && c.contains(RegionId(3)));
    CPPUNIT_ASSERT(!c.contains(RegionId(1)));
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), c.regions.size());
  }

  void costsAndGatewaysChangeNoRegion() {
    const RegionChanges c = regionChanges({event(RgMapEventKind::CostsLearned, 0, 0, 4),
                                           event(RgMapEventKind::GatewayUpdated, 0, 0, 4)});
    CPPUNIT_ASSERT(!c.all);
    CPPUNIT_ASSERT(c.regions.empty());
  }

  void revisedPosesChangeAll() {
    const RegionChanges c = regionChanges({event(RgMapEventKind::PosesRevised, 0)});
    CPPUNIT_ASSERT(c.all);
    CPPUNIT_ASSERT(c.contains(RegionId(7)));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(RegionChangesTest);
