// Validation-based choice of the HMM training configuration; see HmmSelection.h.
#include "tests/eval/crossings/HmmSelection.h"

#include <limits>

#include "tests/eval/crossings/Evaluation.h"
#include "tests/eval/crossings/ParallelFor.h"

namespace rgnav {

std::vector<HmmCandidate> hmmCandidates() {
  std::vector<HmmCandidate> candidates;
  for (const Eigen::Index clusters : {8, 12}) {
    for (const double noise : {0.05, 0.03}) {
      for (const bool learned : {false, true}) {
        HmmCandidate c;
        c.config.clusters = clusters;
        c.config.noiseStdDev = noise;
        if (learned) c.config.em.learnedCovarianceFloor = noise * noise;
        c.validationAccuracy = std::numeric_limits<double>::quiet_NaN();
        candidates.push_back(c);
      }
    }
  }
  return candidates;
}

const char* gaussiansName(const HmmTrainingConfig& config) {
  return config.em.learnedCovarianceFloor ? "learned" : "fixed";
}

std::size_t selectHmmCandidate(std::vector<HmmCandidate>& candidates, const ClassSequences& fit,
                               const ClassSequences& validation, int threads) {
  std::size_t validationCount = 0;
  for (const auto& [c, sequences] : validation) validationCount += sequences.size();
  if (validationCount == 0) return 0;
  parallelFor(candidates.size(), threads, [&](std::size_t i) {
    const HmmClassifier classifier = trainHmmClassifier(fit, candidates[i].config);
    GatewayConfusionMatrix matrix(classifier.classes());
    addHmmClassifications(classifier, validation, matrix);
    candidates[i].validationAccuracy = matrix.meanClassAccuracy();
  });
  std::size_t best = 0;
  for (std::size_t i = 1; i < candidates.size(); ++i)
    if (candidates[i].validationAccuracy > candidates[best].validationAccuracy) best = i;
  return best;
}

}  // namespace rgnav
