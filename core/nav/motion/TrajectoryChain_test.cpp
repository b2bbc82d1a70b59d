// Tests the trajectory chain: segments that join are accepted and looked up by arc length
// (the segment starting at a joint wins there); gaps in position or heading are rejected.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"
#include "core/nav/motion/TrajectoryChain.h"

using rgnav::Pose2D;
using rgnav::TrajectoryChain;
using rgnav::TrajectorySegment;

class TrajectoryChainTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(TrajectoryChainTest);
  CPPUNIT_TEST(joinedSegmentsFormAChain);
  CPPUNIT_TEST(gapsAreRejected);
  CPPUNIT_TEST(emptyChainHasNoEnds);
  CPPUNIT_TEST_SUITE_END();

  // A straight of 2 m, a clothoid to curvature 1 over 1 m, then an arc.
  static TrajectoryChain sample() {
    TrajectoryChain chain;
    chain.append({{0.0, 0.0, 0.0}, 2.0, 0.0, 0.0});
    const TrajectorySegment clothoid{chain.end(), 1.0, 0.0, 1.0};
    chain.append(clothoid);
    chain.append({chain.end(), 0.5, 1.0, 0.0});
    return chain;
  }

 public:
  void joinedSegmentsFormAChain() {
    const TrajectoryChain chain = sample();
    CPPUNIT_ASSERT_EQUAL(std::size_t{3}, chain.segments().size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.5, chain.length(), 1e-12);
    CPPUNIT_ASSERT(chain.poseAt(1.0) == (Pose2D{1.0, 0.0, 0.0}));
    CPPUNIT_ASSERT(chain.poseAt(2.0) == chain.segments()[1].start);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, chain.curvatureAt(1.9), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.5, chain.curvatureAt(2.5), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, chain.sharpnessAt(2.0), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, chain.sharpnessAt(3.0), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, chain.curvatureAt(3.2), 1e-12);
    CPPUNIT_ASSERT(chain.poseAt(10.0) == chain.end());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.5 + 0.5, chain.end().theta, 1e-12);
    // The constructor takes the same segments.
    CPPUNIT_ASSERT(TrajectoryChain(chain.segments()).end() == chain.end());
  }

  void gapsAreRejected() {
    TrajectoryChain chain = sample();
    const Pose2D end = chain.end();
    CPPUNIT_ASSERT_THROW(chain.append({{end.x + 0.002, end.y, end.theta}, 1.0, 0.0, 0.0}),
                         rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(chain.append({{end.x, end.y, end.theta + 0.01}, 1.0, 0.0, 0.0}),
                         rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(chain.append({end, 0.0, 0.0, 0.0}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_EQUAL(std::size_t{3}, chain.segments().size());
    chain.append({{end.x + 0.0005, end.y, end.theta + 0.0005}, 1.0, 0.0, 0.0});
    CPPUNIT_ASSERT_EQUAL(std::size_t{4}, chain.segments().size());
    const std::vector<TrajectorySegment> apart = {{{0.0, 0.0, 0.0}, 1.0, 0.0, 0.0},
                                                  {{1.0, 0.1, 0.0}, 1.0, 0.0, 0.0}};
    CPPUNIT_ASSERT_THROW(TrajectoryChain{apart}, rgnav::InvalidArgumentError);
  }

  void emptyChainHasNoEnds() {
    const TrajectoryChain chain;
    CPPUNIT_ASSERT(chain.empty());
    CPPUNIT_ASSERT_THROW(chain.start(), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(chain.end(), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(chain.poseAt(0.0), rgnav::InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(TrajectoryChainTest);
