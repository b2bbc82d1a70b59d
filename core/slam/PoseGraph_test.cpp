// Tests optimizePoseGraph: a square loop whose odometry-like chain drifts is closed by one loop
// constraint; a wrong loop constraint is down-weighted by the robust loss; bad constraints are
// typed errors.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <vector>

#include "core/common/Errors.h"
#include "core/slam/PoseGraph.h"

using rgnav::Constraint;
using rgnav::Pose2D;

namespace {

// 40 poses around a 10 m x 10 m square, 1 m apart, heading along the path.
std::vector<Pose2D> squareLoop() {
  std::vector<Pose2D> poses;
  Pose2D pose;
  for (int side = 0; side < 4; ++side)
    for (int i = 0; i < 10; ++i) {
      poses.push_back(pose);
      pose = rgnav::compose(pose, {1.0, 0.0, i == 9 ? M_PI / 2 : 0.0});
    }
  return poses;
}

Constraint constraint(Constraint::Kind kind, std::size_t from, std::size_t to, const Pose2D& measurement) {
  Constraint c;
  c.kind = kind;
  c.from = static_cast<rgnav::KeyframeIndex>(from);
  c.to = static_cast<rgnav::KeyframeIndex>(to);
  c.measurement = measurement;
  c.information = Eigen::Vector3d(400.0, 400.0, 2500.0).asDiagonal();
  return c;
}

// Sequential constraints with a heading bias of 0.6 degrees per step, and the poses they chain to.
std::vector<Constraint> driftingChain(const std::vector<Pose2D>& truth, std::vector<Pose2D>& chained) {
  std::vector<Constraint> constraints;
  chained = {truth[0]};
  for (std::size_t i = 1; i < truth.size(); ++i) {
    Pose2D step = rgnav::between(truth[i - 1], truth[i]);
    step.theta += 0.6 * M_PI / 180.0;
    constraints.push_back(constraint(Constraint::Kind::Sequential, i - 1, i, step));
    chained.push_back(rgnav::compose(chained.back(), step));
  }
  return constraints;
}

double maxError(const std::vector<Pose2D>& a, const std::vector<Pose2D>& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::hypot(a[i].x - b[i].x, a[i].y - b[i].y));
  return worst;
}

}  // namespace

class PoseGraphTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PoseGraphTest);
  CPPUNIT_TEST(closesADriftingLoop);
  CPPUNIT_TEST(wrongLoopIsDownWeighted);
  CPPUNIT_TEST(badConstraintsAreTypedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void closesADriftingLoop() {
    const auto truth = squareLoop();
    std::vector<Pose2D> poses;
    auto constraints = driftingChain(truth, poses);
    const double before = maxError(poses, truth);
    CPPUNIT_ASSERT(before > 2.0);
    constraints.push_back(constraint(Constraint::Kind::Loop, 39, 0, rgnav::between(truth[39], truth[0])));
    const auto summary = rgnav::optimizePoseGraph(poses, constraints, {});
    CPPUNIT_ASSERT(summary.usable);
    CPPUNIT_ASSERT(summary.finalCost < summary.initialCost);
    CPPUNIT_ASSERT(maxError(poses, truth) < 0.2 * before);
    CPPUNIT_ASSERT(std::hypot(poses[39].x - truth[39].x, poses[39].y - truth[39].y) < 0.1);
    CPPUNIT_ASSERT_EQUAL(0.0, poses[0].x);  // the first pose is fixed
  }
  void wrongLoopIsDownWeighted() {
    const auto truth = squareLoop();
    std::vector<Constraint> constraints;
    for (std::size_t i = 1; i < truth.size(); ++i)
      constraints.push_back(constraint(Constraint::Kind::Sequential, i - 1, i, rgnav::between(truth[i - 1], truth[i])));
    for (std::size_t i = 0; i < 5; ++i)  // five consistent revisits
      constraints.push_back(constraint(Constraint::Kind::Loop, 35 + i, i, rgnav::between(truth[35 + i], truth[i])));
    Pose2D wrong = rgnav::between(truth[20], truth[0]);
    wrong.x += 3.0;
    constraints.push_back(constraint(Constraint::Kind::Loop, 20, 0, wrong));
    std::vector<Pose2D> poses = truth;
    rgnav::optimizePoseGraph(poses, constraints, {});
    CPPUNIT_ASSERT(maxError(poses, truth) < 0.3);
  }
  void badConstraintsAreTypedErrors() {
    std::vector<Pose2D> poses(3);
    const std::vector<Constraint> outOfRange{constraint(Constraint::Kind::Sequential, 0, 3, {})};
    CPPUNIT_ASSERT_THROW(rgnav::optimizePoseGraph(poses, outOfRange, {}), rgnav::InvalidArgumentError);
    auto singular = constraint(Constraint::Kind::Sequential, 0, 1, {});
    singular.information.setZero();
    const std::vector<Constraint> notDefinite{singular};
    CPPUNIT_ASSERT_THROW(rgnav::optimizePoseGraph(poses, notDefinite, {}), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(PoseGraphTest);
