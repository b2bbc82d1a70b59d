// Particles of a removed region (ParticleRehoming.h): one on a free cell of another region moves
// into it with its map pose unchanged; one on no free cell follows the others; without any
// re-homed, it goes into the lowest fetched region; with nothing fetched either it is dropped.
// Particles of regions still there are left as they were.
#include <cppunit/extensions/HelperMacros.h>

#include "servers/localization/ParticleRehoming.h"

using namespace rgnav;

class ParticleRehomingTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ParticleRehomingTest);
  CPPUNIT_TEST(orphansMoveWhereTheirPoseIsFree);
  CPPUNIT_TEST(homelessFollowTheOthersOrTheLowestFetched);
  CPPUNIT_TEST_SUITE_END();

  // Region `id` with its frame at `frame` and free cells over x, y in [0, 4) of that frame.
  static LocalizationRegion region(std::uint64_t id, const Pose2D& frame) {
    LocalizationRegion r;
    r.id = RegionId(id);
    r.frame = frame;
    r.freespace = FreespaceBitmap::allOccupied(0.2, {0.0, 0.0}, 20, 20);
    for (int row = 0; row < 20; ++row)
      for (int col = 0; col < 20; ++col) r.freespace.setFree(col, row);
    return r;
  }

  static LocalizationMap twoRegions() {
    LocalizationMap map{BeamModelConfig{}};
    map.setRegion(region(2, {10.0, 0.0, 0.5}));
    map.setRegion(region(5, {20.0, 0.0, 0.0}));
    return map;
  }

  static void expectAt(const LocalizationMap& map, const Particle& p, RegionId region, const Pose2D& mapPose) {
    CPPUNIT_ASSERT(p.region == region);
    const Pose2D onMap = compose(map.region(region).frame, p.pose);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(mapPose.x, onMap.x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(mapPose.y, onMap.y, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, normalizeAngle(mapPose.theta - onMap.theta), 1e-9);
  }

 public:
  void orphansMoveWhereTheirPoseIsFree() {
    const LocalizationMap map = twoRegions();
    // Particle 0 stays in region 5; particles 1 and 2 were in a removed region 7.
    const std::vector<Particle> particles{{RegionId(5), {1.0, 1.0, 0.0}, 0.5},
                                          {RegionId(7), {0.0, 0.0, 0.0}, 0.25},
                                          {RegionId(7), {0.0, 0.0, 0.0}, 0.25}};
    const Pose2D inFive{21.5, 2.0, 1.0}, inTwo = compose({10.0, 0.0, 0.5}, {1.0, 1.0, -0.2});
    const std::vector<Particle> out = rehomedParticles(particles, {{1, inFive}, {2, inTwo}}, map, {});
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), out.size());
    CPPUNIT_ASSERT(out[0] == particles[0]);
    expectAt(map, out[1], RegionId(5), inFive);
    expectAt(map, out[2], RegionId(2), inTwo);
    CPPUNIT_ASSERT_EQUAL(0.25, out[2].weight);
  }

  void homelessFollowTheOthersOrTheLowestFetched() {
    const LocalizationMap map = twoRegions();
    const std::vector<Particle> particles(3, Particle{RegionId(7), {0.0, 0.0, 0.0}, 1.0 / 3});
    const Pose2D inFive{22.0, 1.0, 0.0}, nowhere{-50.0, 3.0, 0.2};
    std::vector<Particle> out = rehomedParticles(particles, {{0, inFive}, {1, nowhere}, {2, inFive}}, map, {RegionId(2)});
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), out.size());
    expectAt(map, out[1], RegionId(5), nowhere);  // where the others went, not the fetched region
    out = rehomedParticles(particles, {{0, nowhere}, {1, nowhere}, {2, nowhere}}, map, {RegionId(5), RegionId(2)});
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), out.size());
    for (const Particle& p : out) expectAt(map, p, RegionId(2), nowhere);
    out = rehomedParticles(particles, {{0, inFive}, {1, nowhere}, {2, nowhere}}, LocalizationMap{BeamModelConfig{}}, {});
    CPPUNIT_ASSERT(out.empty());
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ParticleRehomingTest);
