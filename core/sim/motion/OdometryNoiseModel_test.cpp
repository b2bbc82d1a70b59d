// Tests the odometry model: the rot1/trans/rot2 decomposition, error statistics over >= 10 000
// steps against the configured variances (Probabilistic Robotics Table 5.6) and drift, the
// standardised errors of a varied trajectory, seeding, and configuration errors.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/common/Errors.h"
#include "core/sim/motion/OdometryNoiseModel.h"

using rgnav::OdometryMotion;
using rgnav::OdometryNoiseConfig;
using rgnav::OdometryNoiseModel;
using rgnav::Pose2D;

namespace {

struct Moments {
  double mean = 0.0;
  double variance = 0.0;
};

Moments moments(const std::vector<double>& xs) {
  Moments m;
  for (const double x : xs) m.mean += x;
  m.mean /= double(xs.size());
  for (const double x : xs) m.variance += (x - m.mean) * (x - m.mean);
  m.variance /= double(xs.size() - 1);
  return m;
}

// The sample mean lies within 5 standard errors of `mean`, the sample variance within 5
// standard errors (sigma^2 sqrt(2/(n-1)) for Gaussian data) of `variance`.
void assertMoments(const std::vector<double>& xs, double mean, double variance) {
  const Moments m = moments(xs);
  const double n = double(xs.size());
  CPPUNIT_ASSERT_DOUBLES_EQUAL(mean, m.mean, 5.0 * std::sqrt(variance / n));
  CPPUNIT_ASSERT_DOUBLES_EQUAL(variance, m.variance, 5.0 * variance * std::sqrt(2.0 / (n - 1.0)));
}

OdometryNoiseConfig testConfig() {
  OdometryNoiseConfig c;
  c.alpha1 = 0.05;
  c.alpha2 = 0.02;
  c.alpha3 = 0.03;
  c.alpha4 = 0.01;
  c.translationScaleError = 0.02;
  c.rotationBiasPerMetre = 0.04;
  return c;
}

}  // namespace

class OdometryNoiseModelTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(OdometryNoiseModelTest);
  CPPUNIT_TEST(decompositionRoundTrips);
  CPPUNIT_TEST(reversingIsNegativeTranslation);
  CPPUNIT_TEST(errorStatisticsMatchModel);
  CPPUNIT_TEST(standardisedErrorsOfVariedTrajectory);
  CPPUNIT_TEST(noiseFreeDriftIsSystematic);
  CPPUNIT_TEST(sameSeedSameOdometry);
  CPPUNIT_TEST(badConfigIsConfigError);
  CPPUNIT_TEST_SUITE_END();

 public:
  void decompositionRoundTrips() {
    const Pose2D from{1.0, -2.0, 2.5};
    const OdometryMotion m{0.3, 0.7, -0.4};
    const Pose2D to = rgnav::applyMotion(from, m);
    const OdometryMotion back = rgnav::decomposeMotion(from, to);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(m.rot1, back.rot1, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(m.trans, back.trans, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(m.rot2, back.rot2, 1e-12);
    // A pure rotation has no rot1.
    const OdometryMotion turn = rgnav::decomposeMotion(from, {1.0, -2.0, 3.0});
    CPPUNIT_ASSERT_EQUAL(0.0, turn.rot1);
    CPPUNIT_ASSERT_EQUAL(0.0, turn.trans);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.5, turn.rot2, 1e-12);
  }

  void reversingIsNegativeTranslation() {
    const OdometryMotion m = rgnav::decomposeMotion({0.0, 0.0, 0.0}, {-0.5, -0.05, 0.1});
    CPPUNIT_ASSERT(m.trans < 0.0);
    CPPUNIT_ASSERT(std::abs(m.rot1) < 0.2);
    const Pose2D to = rgnav::applyMotion({0.0, 0.0, 0.0}, m);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-0.5, to.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-0.05, to.y, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.1, to.theta, 1e-12);
  }

  // The same true motion 20 000 times; the odometry increments' errors follow the model.
  void errorStatisticsMatchModel() {
    const OdometryNoiseConfig c = testConfig();
    const OdometryMotion truth{0.08, 0.15, -0.05};
    std::vector<Pose2D> poses{{0.0, 0.0, 0.0}};
    for (int k = 0; k < 20000; ++k) poses.push_back(rgnav::applyMotion(poses.back(), truth));
    OdometryNoiseModel model(c, 42);
    const std::vector<Pose2D> odometry = model.odometryPoses(poses, {5.0, 5.0, 1.0});
    CPPUNIT_ASSERT_EQUAL(poses.size(), odometry.size());
    CPPUNIT_ASSERT(odometry.front() == (Pose2D{5.0, 5.0, 1.0}));
    std::vector<double> e1, et, e2;
    for (std::size_t k = 1; k < odometry.size(); ++k) {
      const OdometryMotion m = rgnav::decomposeMotion(odometry[k - 1], odometry[k]);
      e1.push_back(rgnav::normalizeAngle(m.rot1 - truth.rot1));
      et.push_back(m.trans - truth.trans);
      e2.push_back(rgnav::normalizeAngle(m.rot2 - truth.rot2));
    }
    const double r1 = truth.rot1 * truth.rot1, t = truth.trans * truth.trans, r2 = truth.rot2 * truth.rot2;
    const double bias = 0.5 * c.rotationBiasPerMetre * truth.trans;
    assertMoments(e1, bias, c.alpha1 * r1 + c.alpha2 * t);
    assertMoments(et, c.translationScaleError * truth.trans, c.alpha3 * t + c.alpha4 * (r1 + r2));
    assertMoments(e2, bias, c.alpha1 * r2 + c.alpha2 * t);
  }

  // Random arcs, turns on the spot and reversing: every error divided by the model's standard
  // deviation for that step is standard normal.
  void standardisedErrorsOfVariedTrajectory() {
    OdometryNoiseConfig c = testConfig();
    c.translationScaleError = 0.0;
    c.rotationBiasPerMetre = 0.0;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> rot(-0.3, 0.3), trans(-0.1, 0.4);
    std::vector<Pose2D> poses{{0.0, 0.0, 0.0}};
    for (int k = 0; k < 15000; ++k) {
      const OdometryMotion m{rot(rng), k % 10 == 0 ? 0.0 : trans(rng), rot(rng)};
      poses.push_back(rgnav::applyMotion(poses.back(), m));
    }
    OdometryNoiseModel model(c, 3);
    const std::vector<Pose2D> odometry = model.odometryPoses(poses, poses.front());
    std::vector<double> z1, zt, z2;
    for (std::size_t k = 1; k < poses.size(); ++k) {
      const OdometryMotion truth = rgnav::decomposeMotion(poses[k - 1], poses[k]);
      const OdometryMotion m = rgnav::decomposeMotion(odometry[k - 1], odometry[k]);
      const double r1 = truth.rot1 * truth.rot1, t = truth.trans * truth.trans, r2 = truth.rot2 * truth.rot2;
      if (truth.trans == 0.0) {
        // A turn on the spot: all rotation is rot2, translation noise alone moves the robot.
        CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, m.trans, 1e-9 + 6.0 * std::sqrt(c.alpha4 * r2));
        continue;
      }
      z1.push_back(rgnav::normalizeAngle(m.rot1 - truth.rot1) / std::sqrt(c.alpha1 * r1 + c.alpha2 * t));
      zt.push_back((m.trans - truth.trans) / std::sqrt(c.alpha3 * t + c.alpha4 * (r1 + r2)));
      z2.push_back(rgnav::normalizeAngle(m.rot2 - truth.rot2) / std::sqrt(c.alpha1 * r2 + c.alpha2 * t));
    }
    CPPUNIT_ASSERT(z1.size() >= 10000);
    assertMoments(z1, 0.0, 1.0);
    assertMoments(zt, 0.0, 1.0);
    assertMoments(z2, 0.0, 1.0);
  }

  void noiseFreeDriftIsSystematic() {
    OdometryNoiseConfig c;
    c.alpha1 = c.alpha2 = c.alpha3 = c.alpha4 = 0.0;
    c.translationScaleError = 0.05;
    c.rotationBiasPerMetre = 0.1;
    std::vector<Pose2D> poses;
    for (int k = 0; k <= 100; ++k) poses.push_back({0.1 * k, 0.0, 0.0});  // 10 m straight
    OdometryNoiseModel model(c, 1);
    const std::vector<Pose2D> odometry = model.odometryPoses(poses, {});
    // 10 m driven: heading off by 1 rad, path 10.5 m long.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, odometry.back().theta, 1e-9);
    double length = 0.0;
    for (std::size_t k = 1; k < odometry.size(); ++k) {
      length += std::hypot(odometry[k].x - odometry[k - 1].x, odometry[k].y - odometry[k - 1].y);
    }
    CPPUNIT_ASSERT_DOUBLES_EQUAL(10.5, length, 1e-9);
  }

  void sameSeedSameOdometry() {
    std::vector<Pose2D> poses;
    for (int k = 0; k < 200; ++k) poses.push_back({0.05 * k, 0.01 * k, 0.002 * k});
    OdometryNoiseModel a(testConfig(), 11), b(testConfig(), 11), c(testConfig(), 12);
    const auto pa = a.odometryPoses(poses, {});
    const auto pb = b.odometryPoses(poses, {});
    const auto pc = c.odometryPoses(poses, {});
    CPPUNIT_ASSERT(pa == pb);
    CPPUNIT_ASSERT(pa != pc);
    // advance() is the same step the sequence is made of.
    OdometryNoiseModel d(testConfig(), 11);
    CPPUNIT_ASSERT(d.advance(pa[0], poses[0], poses[1]) == pa[1]);
  }

  void badConfigIsConfigError() {
    OdometryNoiseConfig c;
    c.alpha3 = -0.1;
    CPPUNIT_ASSERT_THROW(OdometryNoiseModel(c, 1), rgnav::ConfigError);
    c = OdometryNoiseConfig{};
    c.translationScaleError = -1.0;
    CPPUNIT_ASSERT_THROW(OdometryNoiseModel(c, 1), rgnav::ConfigError);
    c = OdometryNoiseConfig{};
    c.rotationBiasPerMetre = INFINITY;
    CPPUNIT_ASSERT_THROW(OdometryNoiseModel(c, 1), rgnav::ConfigError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(OdometryNoiseModelTest);
