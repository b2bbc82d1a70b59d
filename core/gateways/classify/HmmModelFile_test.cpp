// Tests HMM model files: an exact round trip of every parameter, comments, and typed errors for
// a missing file and for corrupted content (truncation, version, numbers, invalid models).
#include "core/gateways/classify/HmmModelFile.h"

#include <cppunit/extensions/HelperMacros.h>

#include <fstream>
#include <numbers>
#include <sstream>

#include "core/common/Errors.h"
#include "core/gateways/classify/testing/SyntheticHmm.h"
#include "core/logs/LogTestFiles.h"

using rgnav::GatewayClass;
using rgnav::testing::TempDir;

namespace {

// Three classes; the Deadend model has a two-component state with a correlated covariance and
// irrational-looking numbers, so that a lossy number format would show.
rgnav::HmmClassifier classifier() {
  const Eigen::Vector3d a(0.1, 0.2, 0.3);
  const Eigen::Vector3d b(0.7, 0.5, 1.0 / 3.0);
  rgnav::GaussianMixtureHmm deadEnd = rgnav::testing::leftRightHmm({a, b}, 0.1, 0.6);
  deadEnd.prior = Eigen::Vector2d(2.0 / 3.0, 1.0 / 3.0);
  Eigen::Matrix3d covariance = 0.02 * Eigen::Matrix3d::Identity();
  covariance(0, 1) = covariance(1, 0) = 0.01 / 7.0;
  deadEnd.states[1].components.emplace_back(Eigen::Vector3d(std::numbers::pi / 10.0, 0.25, 0.5), covariance);
  deadEnd.states[1].mixtureWeights = Eigen::Vector2d(0.1, 0.9);
  return rgnav::HmmClassifier({{GatewayClass::DeadEnd, deadEnd, 0.2},
                               {GatewayClass::XCrossing, rgnav::testing::leftRightHmm({b, a, b}, 0.2, 0.8), 0.5},
                               {GatewayClass::Hallway, rgnav::testing::leftRightHmm({a}, 0.3, 1.0), 0.3}});
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  CPPUNIT_ASSERT(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

class HmmModelFileTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(HmmModelFileTest);
  CPPUNIT_TEST(roundTripKeepsEveryParameter);
  CPPUNIT_TEST(acceptsCommentsAndBlankLines);
  CPPUNIT_TEST(missingFileIsAFileError);
  CPPUNIT_TEST(corruptedFilesAreFormatErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void roundTripKeepsEveryParameter() {
    TempDir dir;
    const rgnav::HmmClassifier original = classifier();
    rgnav::saveHmmModels(dir.file("models.txt"), original);
    const rgnav::HmmClassifier loaded = rgnav::loadHmmModels(dir.file("models.txt"));
    CPPUNIT_ASSERT(loaded.classes() == original.classes());
    CPPUNIT_ASSERT(loaded.priors() == original.priors());
    for (std::size_t i = 0; i < original.models().size(); ++i) {
      const rgnav::GaussianMixtureHmm& a = original.models()[i].hmm;
      const rgnav::GaussianMixtureHmm& b = loaded.models()[i].hmm;
      CPPUNIT_ASSERT(a.prior == b.prior);
      CPPUNIT_ASSERT(a.transitions == b.transitions);
      CPPUNIT_ASSERT_EQUAL(a.states.size(), b.states.size());
      for (std::size_t j = 0; j < a.states.size(); ++j) {
        CPPUNIT_ASSERT(a.states[j].mixtureWeights == b.states[j].mixtureWeights);
        for (std::size_t m = 0; m < a.states[j].components.size(); ++m) {
          CPPUNIT_ASSERT(a.states[j].components[m].mean() == b.states[j].components[m].mean());
          CPPUNIT_ASSERT(a.states[j].components[m].covariance() == b.states[j].components[m].covariance());
        }
      }
    }
    const rgnav::GatewayObservationSequence s = {{3.0, Eigen::Vector3d(0.2, 0.3, 0.4)},
                                                 {2.0, Eigen::Vector3d(0.6, 0.5, 0.3)}};
    CPPUNIT_ASSERT(loaded.logLikelihoods(s) == original.logLikelihoods(s));
    // Saving the loaded models gives the same file.
    rgnav::saveHmmModels(dir.file("again.txt"), loaded);
    CPPUNIT_ASSERT_EQUAL(readText(dir.file("models.txt")), readText(dir.file("again.txt")));
  }

  void acceptsCommentsAndBlankLines() {
    TempDir dir;
    rgnav::saveHmmModels(dir.file("models.txt"), classifier());
    const std::string text = readText(dir.file("models.txt"));
    writeText(dir.file("commented.txt"),
              "# trained on 2m cluttered\n\n" + replaced(text, "end\n", "  # done\nend\n\n"));
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), rgnav::loadHmmModels(dir.file("commented.txt")).models().size());
  }

  void missingFileIsAFileError() {
    TempDir dir;
    CPPUNIT_ASSERT_THROW(rgnav::loadHmmModels(dir.file("none.txt")), rgnav::FileError);
  }

  void corruptedFilesAreFormatErrors() {
    TempDir dir;
    rgnav::saveHmmModels(dir.file("models.txt"), classifier());
    const std::string text = readText(dir.file("models.txt"));
    const std::vector<std::string> corrupted = {
        "",
        "garbage\n",
        text.substr(0, text.size() - 4),  // no end
        text.substr(0, text.size() / 2),  // cut mid-way
        replaced(text, "rgnav-gateway-hmms 1", "rgnav-gateway-hmms 2"),
        replaced(text, "dimension 3", "dimension 4"),
        replaced(text, "model Deadend", "model Dead-End"),
        replaced(text, "model Hallway", "model Deadend"),  // a class given twice
        replaced(text, "model Hallway 0.3", "model Hallway 0"),
        replaced(text, "prior 0.6666666666666666", "prior 0.6666666666666666x"),
        replaced(text, "prior 0.6666666666666666", "prior 0.7666666666666666"),
        replaced(text, "transitions 0.6 0.4", "transitions 0.6 0.4 0"),
        replaced(text, "component 0.1", "component -0.1"),
        replaced(text, "covariance 0.02 0.0014285714285714286", "covariance 0.02 0.5"),  // not symmetric
        replaced(text, "covariance 0.010000000000000002", "covariance -0.01"),           // not positive definite
        replaced(text, "state 2", "state 3"),
        text + "model Hallway 1 1\n",
    };
    for (std::size_t i = 0; i < corrupted.size(); ++i) {
      writeText(dir.file("bad.txt"), corrupted[i]);
      try {
        rgnav::loadHmmModels(dir.file("bad.txt"));
        CPPUNIT_FAIL("corruption " + std::to_string(i) + " was accepted");
      } catch (const rgnav::FormatError& e) {
        CPPUNIT_ASSERT_EQUAL(dir.file("bad.txt"), e.file());
      }
    }
    // The error names the line of the bad number.
    writeText(dir.file("bad.txt"), replaced(text, "prior 0.6666666666666666", "prior nonsense"));
    try {
      rgnav::loadHmmModels(dir.file("bad.txt"));
      CPPUNIT_FAIL("bad number accepted");
    } catch (const rgnav::FormatError& e) {
      CPPUNIT_ASSERT_EQUAL(std::size_t(5), e.line());
    }
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(HmmModelFileTest);
