// Tests of the parts of the region MCL: likelihood field, odometry sampling, KLD bound,
// low-variance resampling and particle clusters.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"
#include "core/nav/localization/KldSampling.h"
#include "core/nav/localization/LikelihoodField.h"
#include "core/nav/localization/LowVarianceResampler.h"
#include "core/nav/localization/OdometrySampler.h"
#include "core/nav/localization/ParticleClusters.h"

using namespace rgnav;

class FilterPartsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(FilterPartsTest);
  CPPUNIT_TEST(fieldPeaksOnTheLine);
  CPPUNIT_TEST(fieldScoresAPointOutsideAsRandom);
  CPPUNIT_TEST(fieldScoresAScanBestAtItsTruePose);
  CPPUNIT_TEST(samplerWithoutNoiseMovesExactly);
  CPPUNIT_TEST(samplerSpreadGrowsWithTheAlphas);
  CPPUNIT_TEST(kldBoundGrowsWithTheBinsAndIsClamped);
  CPPUNIT_TEST(lowVarianceDrawFollowsTheWeights);
  CPPUNIT_TEST(clustersAreHeaviestFirstWithTheirMeans);
  CPPUNIT_TEST_SUITE_END();

 public:
  void fieldPeaksOnTheLine() {
    const std::vector<Segment2> lines{{{0, 0}, {2, 0}}};
    const LikelihoodField field(lines, BeamModelConfig{});
    const double on = field.logLikelihood(Eigen::Vector2d(1.0, 0.01));
    const double near = field.logLikelihood(Eigen::Vector2d(1.0, 0.1));
    const double far = field.logLikelihood(Eigen::Vector2d(1.0, 0.5));
    CPPUNIT_ASSERT(on > near);
    CPPUNIT_ASSERT(near > far);
    CPPUNIT_ASSERT(field.bytes() > 0);
  }

  void fieldScoresAPointOutsideAsRandom() {
    const BeamModelConfig config;
    const std::vector<Segment2> lines{{{0, 0}, {2, 0}}};
    const LikelihoodField field(lines, config);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(std::log(config.zRand / config.maxRangeM), field.logLikelihood(Eigen::Vector2d(50, 50)), 1e-6);
    const LikelihoodField empty(std::vector<Segment2>{}, config);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(std::log(config.zRand / config.maxRangeM), empty.logLikelihood(Eigen::Vector2d(0, 0)), 1e-6);
  }

  void fieldScoresAScanBestAtItsTruePose() {
    const std::vector<Segment2> lines{{{0, 0}, {4, 0}}, {{0, 0}, {0, 4}}};
    const LikelihoodField field(lines, BeamModelConfig{});
    ScanBeams beams;  // seen from (1, 1, 0): points on both walls
    for (double t = -0.8; t <= 2.5; t += 0.3) beams.endpoints.emplace_back(t, -1.0);
    for (double t = -0.8; t <= 2.5; t += 0.3) beams.endpoints.emplace_back(-1.0, t);
    const double truth = field.logLikelihood(Pose2D{1, 1, 0}, beams);
    CPPUNIT_ASSERT(truth > field.logLikelihood(Pose2D{1.2, 1, 0}, beams));
    CPPUNIT_ASSERT(truth > field.logLikelihood(Pose2D{1, 1, 0.1}, beams));
  }

  void samplerWithoutNoiseMovesExactly() {
    OdometrySampler sampler(MotionModelConfig{0, 0, 0, 0}, 1);
    const Pose2D from{1, 2, 0.5}, to{2, 2.5, 1.0};
    const Pose2D moved = sampler.sample(Pose2D{}, decomposeMotion(from, to));
    const Pose2D expected = between(from, to);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(expected.x, moved.x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(expected.y, moved.y, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(expected.theta, moved.theta, 1e-9);
  }

  void samplerSpreadGrowsWithTheAlphas() {
    const auto spread = [](double alpha) {
      OdometrySampler sampler(MotionModelConfig{alpha, alpha, alpha, alpha}, 7);
      const OdometryMotion motion = decomposeMotion(Pose2D{}, Pose2D{1, 0, 0});
      double sum = 0.0, sumSq = 0.0;
      for (int i = 0; i < 2000; ++i) {
        const Pose2D moved = sampler.sample(Pose2D{}, motion);
        const double x = std::hypot(moved.x, moved.y);  // the sampled translation
        sum += x;
        sumSq += x * x;
      }
      const double mean = sum / 2000.0;
      CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, mean, 0.02);
      return std::sqrt(sumSq / 2000.0 - mean * mean);
    };
    const double small = spread(0.001), large = spread(0.05);
    CPPUNIT_ASSERT(large > 3.0 * small);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(std::sqrt(0.05), large, 0.03);
  }

  void kldBoundGrowsWithTheBinsAndIsClamped() {
    KldConfig config;
    CPPUNIT_ASSERT_EQUAL(config.minParticles, kldParticleBound(1, config));
    const std::size_t ten = kldParticleBound(10, config), hundred = kldParticleBound(100, config);
    CPPUNIT_ASSERT(hundred > ten);
    CPPUNIT_ASSERT(ten >= config.minParticles);
    CPPUNIT_ASSERT_EQUAL(config.maxParticles, kldParticleBound(100000, config));
    // Fox 2003, table/figure: k = 100, eps = 0.05, delta = 0.01 gives about 1200 particles.
    config.maxParticles = 100000;
    CPPUNIT_ASSERT(kldParticleBound(100, config) > 1100 && kldParticleBound(100, config) < 1400);
    KldBins bins(config);
    CPPUNIT_ASSERT(bins.add(1, Pose2D{0.05, 0.05, 0}));
    CPPUNIT_ASSERT(!bins.add(1, Pose2D{0.1, 0.1, 0.01}));
    CPPUNIT_ASSERT(bins.add(2, Pose2D{0.05, 0.05, 0}));
    CPPUNIT_ASSERT(bins.add(1, Pose2D{0.05, 0.05, 1.0}));
    CPPUNIT_ASSERT_EQUAL(std::size_t{3}, bins.occupied());
  }

  void lowVarianceDrawFollowsTheWeights() {
    std::mt19937_64 rng(3);
    const std::vector<double> weights{0.0, 0.75, 0.0, 0.25};
    const std::vector<std::size_t> drawn = lowVarianceDraw(weights, 100, rng);
    CPPUNIT_ASSERT_EQUAL(std::size_t{100}, drawn.size());
    const auto count = [&](std::size_t i) { return std::count(drawn.begin(), drawn.end(), i); };
    CPPUNIT_ASSERT_EQUAL(std::ptrdiff_t{0}, count(0) + count(2));
    CPPUNIT_ASSERT(count(1) >= 74 && count(1) <= 76);
    CPPUNIT_ASSERT_THROW(lowVarianceDraw(std::vector<double>{0.0, 0.0}, 4, rng), InvalidArgumentError);
  }

  void clustersAreHeaviestFirstWithTheirMeans() {
    const RegionId r{1};
    const std::vector<Particle> particles{{r, {}, 0.2}, {r, {}, 0.2}, {r, {}, 0.3}, {r, {}, 0.3}};
    const std::vector<Pose2D> poses{{0, 0, M_PI - 0.05}, {0.2, 0, -M_PI + 0.05}, {5, 5, 0}, {5.2, 5, 0.1}};
    const std::vector<ParticleCluster> clusters = clusterParticles(particles, poses, 0.5, 0.5);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, clusters.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.6, clusters[0].weight, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(5.1, clusters[0].mean.x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.05, clusters[0].mean.theta, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.1, clusters[1].mean.x, 1e-9);
    // The heading mean is circular: across +-pi it is pi, not 0.
    CPPUNIT_ASSERT(std::abs(std::abs(clusters[1].mean.theta) - M_PI) < 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.01, clusters[1].covariance(0, 0), 1e-9);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(FilterPartsTest);
