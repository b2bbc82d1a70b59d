// Tests corrected poses by scan ID on a hand-made state: keyframes keep their pose, filtered scans
// are interpolated through odometry between the surrounding keyframes, and odomToMap picks the
// transform of the nearest scan by ID (thesis 3.3.5), even where the odometry poses coincide;
// poses as mapped and after a kept revision.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"
#include "core/slam/CorrectedPoses.h"

using rgnav::Pose2D;

namespace {

bool near(const Pose2D& a, const Pose2D& b) {
  return std::hypot(a.x - b.x, a.y - b.y) < 1e-9 && std::abs(rgnav::normalizeAngle(a.theta - b.theta)) < 1e-9;
}

// Scans 10..14 with odometry along x; keyframes at 10 and 14; the map shifted by +1 in y at
// keyframe 10 and by +2 at keyframe 14 (the odometry drifted in between). Scan 20 comes back to
// scan 12's odometry pose after the map learned of a different correction (a revisit).
rgnav::SlamState handMade() {
  rgnav::SlamState state;
  state.keyframes.push_back({10, {0, 0, 0}, {0, 1, 0}, {}});
  state.keyframes.push_back({14, {4, 0, 0}, {4, 2, 0}, {}});
  state.keyframes.push_back({20, {2, 0, 0}, {2, 5, 0}, {}});
  for (rgnav::DataId id = 10; id <= 14; ++id) {
    const bool keyframe = id == 10 || id == 14;
    const rgnav::KeyframeIndex previous = id < 14 ? 0 : 1;
    state.scans.push_back(
        {id, double(id), {double(id - 10), 0, 0}, keyframe ? previous : rgnav::kNoKeyframe, previous, {}});
  }
  state.scans.push_back({20, 20.0, {2, 0, 0}, 2, 2, {7, 7, 0}});
  return state;
}

}  // namespace

class CorrectedPosesTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CorrectedPosesTest);
  CPPUNIT_TEST(keyframesKeepTheirPose);
  CPPUNIT_TEST(filteredScansAreInterpolated);
  CPPUNIT_TEST(odomToMapUsesTheNearestScanById);
  CPPUNIT_TEST(unknownIdsAreTypedErrors);
  CPPUNIT_TEST(mappedPoseIsTheStoredOne);
  CPPUNIT_TEST(revisedPosesUseTheRevisionsKeyframes);
  CPPUNIT_TEST_SUITE_END();

 public:
  void keyframesKeepTheirPose() {
    const auto state = handMade();
    CPPUNIT_ASSERT(near(Pose2D{0, 1, 0}, rgnav::correctedPose(state, 10)));
    CPPUNIT_ASSERT(near(Pose2D{4, 2, 0}, rgnav::correctedPose(state, 14)));
  }
  void filteredScansAreInterpolated() {
    const auto state = handMade();
    // Scan 11: 1/4 of the way from keyframe 10 to 14: y = 1 + (2 - 1) / 4.
    CPPUNIT_ASSERT(near(Pose2D{1, 1.25, 0}, rgnav::correctedPose(state, 11)));
    CPPUNIT_ASSERT(near(Pose2D{3, 1.75, 0}, rgnav::correctedPose(state, 13)));
  }
  void odomToMapUsesTheNearestScanById() {
    const auto state = handMade();
    // An object 1 m ahead of odometry pose (2, 0) seen at scan 12 and at scan 20: same odometry,
    // different visits, different corrections.
    CPPUNIT_ASSERT(near(Pose2D{3, 1.5, 0}, rgnav::odomToMap(state, 12, {3, 0, 0})));
    CPPUNIT_ASSERT(near(Pose2D{3, 5, 0}, rgnav::odomToMap(state, 20, {3, 0, 0})));
    // IDs not held: nearest by ID (17 is 3 from 14 and 20: the earlier), 18 -> 20, beyond -> 20.
    CPPUNIT_ASSERT(near(Pose2D{4, 2, 0}, rgnav::odomToMap(state, 17, {4, 0, 0})));
    CPPUNIT_ASSERT(near(Pose2D{2, 5, 0}, rgnav::odomToMap(state, 18, {2, 0, 0})));
    CPPUNIT_ASSERT(near(Pose2D{2, 5, 0}, rgnav::odomToMap(state, 99, {2, 0, 0})));
    CPPUNIT_ASSERT(near(Pose2D{0, 1, 0}, rgnav::odomToMap(state, 1, {0, 0, 0})));
  }
  void unknownIdsAreTypedErrors() {
    const auto state = handMade();
    CPPUNIT_ASSERT_THROW(rgnav::correctedPose(state, 15), rgnav::NotAvailableError);
    CPPUNIT_ASSERT_THROW(rgnav::correctedPose(state, 9), rgnav::NotAvailableError);
    CPPUNIT_ASSERT_THROW(rgnav::odomToMap(rgnav::SlamState{}, 1, {}), rgnav::NotAvailableError);
  }
  void mappedPoseIsTheStoredOne() {
    const auto state = handMade();
    CPPUNIT_ASSERT(near(Pose2D{7, 7, 0}, rgnav::mappedPose(state, 20)));
    CPPUNIT_ASSERT_THROW(rgnav::mappedPose(state, 15), rgnav::NotAvailableError);
  }
  void revisedPosesUseTheRevisionsKeyframes() {
    auto state = handMade();
    // Revision 3 ran while scan 14 was input and knew keyframe 10 only; revision 4 ran after the
    // input (at 21) and knew all three keyframes, with other poses than the current ones.
    state.counters.optimizations = 4;
    state.revisions.push_back({3, 14, {{0, 3, 0}}});
    state.revisions.push_back({4, 21, {{0, -1, 0}, {4, -2, 0}, {2, 9, 0}}});
    // Scan 11 after revision 3: keyframe 10's prediction alone (no later keyframe then).
    CPPUNIT_ASSERT(near(Pose2D{1, 3, 0}, rgnav::revisedPose(state, 11, 3)));
    // After revision 4: interpolated between its poses of keyframes 10 and 14.
    CPPUNIT_ASSERT(near(Pose2D{1, -1.25, 0}, rgnav::revisedPose(state, 11, 4)));
    CPPUNIT_ASSERT(near(Pose2D{2, 9, 0}, rgnav::revisedPose(state, 20, 4)));
    // Scan 14 was input while revision 3 ran: not revised by it.
    CPPUNIT_ASSERT_THROW(rgnav::revisedPose(state, 14, 3), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::revisedPose(state, 11, 2), rgnav::NotAvailableError);
    CPPUNIT_ASSERT_THROW(rgnav::revisedPose(state, 15, 4), rgnav::NotAvailableError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(CorrectedPosesTest);
