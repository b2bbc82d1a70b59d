// HmmSelection: the choice of the HMM training configuration, thesis 4.1.3.3: "the task to find
// the best HMM is to optimize the learning with regard to the number of clusters and the noise
// to be added ... By now we semiautomatically search for an optimal solution". Here the search
// is automatic, also decides whether EM learns the Gaussians (which the thesis keeps fixed), and
// never looks at the test data: every candidate is trained on the fit part of
// the training data and scored on the held-out validation part by its mean per-class
// recognition rate (counter-class included); the best one (the first on a tie) wins.
#pragma once

#include <vector>

#include "core/gateways/classify/HmmTrainer.h"
#include "tests/eval/crossings/CrossingData.h"

namespace rgnav {

struct HmmCandidate {
  HmmTrainingConfig config;
  double validationAccuracy = 0.0;  // mean per-class rate; NaN when nothing was validated
};

// Clusters {8, 12} x noise {0.03, 0.05} x Gaussians fixed (the thesis) or learned by EM with
// the noise variance as their floor (BaumWelch.h), the rest as HmmTrainingConfig's defaults;
// the first candidate is HmmTrainingConfig's default.
std::vector<HmmCandidate> hmmCandidates();

// "fixed" or "learned".
const char* gaussiansName(const HmmTrainingConfig& config);

// Scores the candidates (trained on `threads` threads) and returns the index of the best one;
// without validation sequences nothing is trained and the index is 0.
std::size_t selectHmmCandidate(std::vector<HmmCandidate>& candidates, const ClassSequences& fit,
                               const ClassSequences& validation, int threads);

}  // namespace rgnav
