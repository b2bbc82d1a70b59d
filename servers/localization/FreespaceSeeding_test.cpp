// Global seeding over the freespace (FreespaceSeeding.h): every particle lies on a free cell of
// its region, both regions get particles in proportion to their free cells, headings cover the
// circle, and a map without freespace is NotAvailable.
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "servers/localization/FreespaceSeeding.h"

using namespace rgnav;

class FreespaceSeedingTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(FreespaceSeedingTest);
  CPPUNIT_TEST(particlesLieOnFreeCells);
  CPPUNIT_TEST(noFreespaceIsNotAvailable);
  CPPUNIT_TEST_SUITE_END();

  // A region whose bitmap of 15 cm cells is 2 cols x 4 cells, its left `cols` columns free.
  static LocalizationRegion region(std::uint64_t id, const Pose2D& frame, int cols) {
    LocalizationRegion r;
    r.id = RegionId(id);
    r.frame = frame;
    r.freespace = FreespaceBitmap::allOccupied(0.15, {-1.0, -1.0}, 2 * cols, 4);
    for (int row = 0; row < 4; ++row)
      for (int col = 0; col < cols; ++col) r.freespace.setFree(col, row);
    return r;
  }

 public:
  void particlesLieOnFreeCells() {
    LocalizationMap map{BeamModelConfig{}};
    map.setRegion(region(1, {0, 0, 0}, 10));
    map.setRegion(region(2, {5, 0, 1.0}, 30));
    std::mt19937_64 rng(7);
    const std::vector<Particle> particles = uniformFreespaceParticles(map, 4000, rng);
    CPPUNIT_ASSERT_EQUAL(std::size_t(4000), particles.size());
    std::size_t inSecond = 0, turnedLeft = 0;
    for (const Particle& p : particles) {
      CPPUNIT_ASSERT(map.region(p.region).freespace.isFreeAt({p.pose.x, p.pose.y}));
      CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0 / 4000, p.weight, 1e-15);
      inSecond += p.region == RegionId(2);
      turnedLeft += p.pose.theta > 0.0;
    }
    // 40 and 120 free cells: three quarters in region 2 (binomial sd about 27).
    CPPUNIT_ASSERT(inSecond > 2850 && inSecond < 3150);
    CPPUNIT_ASSERT(turnedLeft > 1850 && turnedLeft < 2150);
  }

  void noFreespaceIsNotAvailable() {
    LocalizationMap map{BeamModelConfig{}};
    std::mt19937_64 rng(7);
    CPPUNIT_ASSERT_THROW(uniformFreespaceParticles(map, 10, rng), NotAvailableError);
    map.setRegion(region(1, {0, 0, 0}, 0));
    CPPUNIT_ASSERT_THROW(uniformFreespaceParticles(map, 10, rng), NotAvailableError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(FreespaceSeedingTest);
