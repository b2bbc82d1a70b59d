// Tables: the printed form of the crossing evaluation. Table 4.2 (per environment: the number of
// test sequences per class out of the approaches driven - an approach whose gateway was never
// tracked gives none -, then the recognition rate of ASC, SOC on the last and on the last but
// one observation, and of the multi-class HMM), table 4.3 (pairwise HMMs: the rates of the two
// classes per environment), the multi-class HMM confusion matrices (all environments, the
// 2 m cluttered ones, each environment), the HMM errors per test gateway (clutter layout) and the
// rates of the Bayes fusion per gateway.
#pragma once

#include <ostream>

#include "tests/eval/crossings/CrossingData.h"
#include "tests/eval/crossings/Evaluation.h"

namespace rgnav {

void printTable42(std::ostream& out, const CrossingData& data, const CrossingResults& results);
void printTable43(std::ostream& out, const CrossingResults& results);
void printConfusionMatrices(std::ostream& out, const CrossingResults& results);
void printLayoutErrors(std::ostream& out, const CrossingResults& results);
void printFusion(std::ostream& out, const CrossingResults& results);

}  // namespace rgnav
