// Tests ScanMapper end to end on a synthetic ring corridor driven twice with drifting odometry:
// scans are filtered, registered, the loop is closed, every scan ID gets a corrected pose close to
// the truth; the poses as mapped and the kept revisions give the poses a follower saw at each
// step; and the argument checks.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <utility>
#include <vector>

#include "core/common/Errors.h"
#include "core/slam/ScanMapper.h"
#include "core/slam/testing/SyntheticWorld.h"

using rgnav::Pose2D;

namespace {

using Run = rgnav::testing::SyntheticRun;

double worstError(const rgnav::ScanMapper& mapper, const Run& run, bool useOdometry) {
  double worst = 0.0;
  for (std::size_t i = 0; i < run.scans.size(); ++i) {
    const Pose2D p = useOdometry ? run.scans[i].odometry : mapper.correctedPose(run.scans[i].id);
    worst = std::max(worst, std::hypot(p.x - run.truth[i].x, p.y - run.truth[i].y));
  }
  return worst;
}

}  // namespace

class ScanMapperTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ScanMapperTest);
  CPPUNIT_TEST(closesTheRingAndCorrectsEveryScan);
  CPPUNIT_TEST(odomToMapUsesTheTransformAtTheScan);
  CPPUNIT_TEST(keepsThePosesOfEachStep);
  CPPUNIT_TEST(keepsTheLatestRevisionsOnly);
  CPPUNIT_TEST(rejectsRepeatedIdsAndBadConfig);
  CPPUNIT_TEST_SUITE_END();

 public:
  void closesTheRingAndCorrectsEveryScan() {
    const Run run = rgnav::testing::ringRun();
    rgnav::ScanMapper mapper;
    std::size_t keyframes = 0;
    for (const auto& scan : run.scans) keyframes += mapper.addScan(scan).keyframe ? 1 : 0;
    mapper.optimize();
    const auto& state = mapper.state();
    CPPUNIT_ASSERT_EQUAL(keyframes, state.keyframes.size());
    CPPUNIT_ASSERT(keyframes < run.scans.size() * 6 / 10);  // 0.1 m steps, 0.2 m filter; corners all kept
    CPPUNIT_ASSERT(state.counters.loopClosures > 10);
    CPPUNIT_ASSERT(state.counters.optimizations > 0);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{0}, state.counters.failedRegistrations);
    CPPUNIT_ASSERT(worstError(mapper, run, true) > 2.0);
    CPPUNIT_ASSERT(worstError(mapper, run, false) < 0.1);
    CPPUNIT_ASSERT_EQUAL(run.scans.back().id, mapper.lastInputId());
  }
  void odomToMapUsesTheTransformAtTheScan() {
    const Run run = rgnav::testing::ringRun();
    rgnav::ScanMapper mapper;
    for (std::size_t i = 0; i < 400; ++i) mapper.addScan(run.scans[i]);
    const auto& scan = run.scans[300];
    const Pose2D odometryPose = rgnav::compose(scan.odometry, {0.5, -0.2, 0.3});  // an object seen from there
    const Pose2D mapped = mapper.odomToMap(scan.id, odometryPose);
    const Pose2D expected = rgnav::compose(mapper.correctedPose(scan.id), {0.5, -0.2, 0.3});
    CPPUNIT_ASSERT(std::hypot(mapped.x - expected.x, mapped.y - expected.y) < 1e-9);
    CPPUNIT_ASSERT_THROW(mapper.correctedPose(401), rgnav::NotAvailableError);
    // An ID beyond the last uses the last scan's transform.
    const Pose2D late = mapper.odomToMap(1000, run.scans[399].odometry);
    const Pose2D last = mapper.correctedPose(400);
    CPPUNIT_ASSERT(std::hypot(late.x - last.x, late.y - last.y) < 1e-9);
  }
  void keepsThePosesOfEachStep() {
    // A follower that reads every pose right after each scan sees what the mapper kept.
    const Run run = rgnav::testing::ringRun();
    rgnav::ScanMapper mapper;
    std::vector<std::pair<std::uint64_t, std::vector<Pose2D>>> seenAfterRevisions;
    for (const auto& scan : run.scans) {
      const rgnav::ScanOutcome outcome = mapper.addScan(scan);
      CPPUNIT_ASSERT(mapper.mappedPose(scan.id) == mapper.correctedPose(scan.id));
      if (!outcome.optimized) continue;
      std::vector<Pose2D> before;
      for (const auto& s : mapper.state().scans)
        if (s.id < scan.id) before.push_back(mapper.correctedPose(s.id));
      seenAfterRevisions.emplace_back(mapper.state().counters.optimizations, before);
    }
    CPPUNIT_ASSERT(seenAfterRevisions.size() > 1);
    for (const auto& [revision, poses] : seenAfterRevisions) {
      CPPUNIT_ASSERT_EQUAL(revision, mapper.state().revisions[revision - 1].number);
      for (std::size_t i = 0; i < poses.size(); ++i)
        CPPUNIT_ASSERT(mapper.revisedPose(mapper.state().scans[i].id, revision) == poses[i]);  // bit-exact
    }
    // A scan mapped after a revision was made is not revised by it.
    const auto& first = mapper.state().revisions.front();
    CPPUNIT_ASSERT_THROW(mapper.revisedPose(first.atScan, first.number), rgnav::InvalidArgumentError);
  }
  void keepsTheLatestRevisionsOnly() {
    const Run run = rgnav::testing::ringRun();
    rgnav::SlamConfig config;
    config.graph.keptRevisions = 2;
    rgnav::ScanMapper mapper(config);
    for (const auto& scan : run.scans) mapper.addScan(scan);
    const auto& state = mapper.state();
    CPPUNIT_ASSERT(state.counters.optimizations > 2);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, state.revisions.size());
    CPPUNIT_ASSERT_EQUAL(state.counters.optimizations, state.revisions.back().number);
    CPPUNIT_ASSERT_THROW(mapper.revisedPose(1, state.counters.optimizations - 2), rgnav::NotAvailableError);
    mapper.forgetRevisionsUpTo(state.counters.optimizations - 1);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, state.revisions.size());
    CPPUNIT_ASSERT_EQUAL(state.counters.optimizations, state.revisions.front().number);
  }
  void rejectsRepeatedIdsAndBadConfig() {
    const Run run = rgnav::testing::ringRun();
    rgnav::ScanMapper mapper;
    mapper.addScan(run.scans[0]);
    mapper.addScan(run.scans[1]);
    CPPUNIT_ASSERT_THROW(mapper.addScan(run.scans[1]), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, mapper.state().scans.size());
    CPPUNIT_ASSERT_THROW(rgnav::ScanMapper().odomToMap(1, {}), rgnav::NotAvailableError);
    rgnav::SlamConfig bad;
    bad.local.grid.resolution = 0.0;
    CPPUNIT_ASSERT_THROW(rgnav::ScanMapper{bad}, rgnav::ConfigError);
    rgnav::SlamConfig noRevisions;
    noRevisions.graph.keptRevisions = 0;
    CPPUNIT_ASSERT_THROW(rgnav::ScanMapper{noRevisions}, rgnav::ConfigError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(ScanMapperTest);
