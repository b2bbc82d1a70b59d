// QuadrangleGrouping: 2D line grouping to quadrangle hypotheses, thesis 3.1 and figure 3.2.
// twoStage: stage 1 keeps the neighbour pairs among all C(N,2) pairs of lines; stage 2 tries
// every two disjoint neighbour pairs with the rules of figure 3.2 (QuadrangleRules).
// naive: the straightforward search the thesis starts from, every one of the C(N,4) sets of four
// lines in its three ways of splitting into two pairs, each checked with the same rules; it finds
// the same hypotheses and serves as reference and test oracle.
// group: twoStage, then hypotheses contained in or strongly overlapping larger ones are removed
// (3.2), so the result marks the larger regions of interest.
#pragma once

#include <vector>

#include "core/objects/Quadrangle.h"
#include "core/objects/QuadrangleRules.h"

namespace rgnav {

class QuadrangleGrouping {
 public:
  // Throws InvalidArgumentError for invalid parameters (see validate).
  explicit QuadrangleGrouping(const GroupingParams& params = {});

  // All hypotheses, each once, sorted by their side cycles.
  std::vector<Quadrangle> twoStage(const std::vector<LineSegment>& lines) const;
  std::vector<Quadrangle> naive(const std::vector<LineSegment>& lines) const;

  // twoStage without the hypotheses covered by larger ones, largest first (see
  // removeContainedAndOverlapping; the thesis gives no overlap value).
  std::vector<Quadrangle> group(const std::vector<LineSegment>& lines, double maxOverlapRatio = 0.5) const;

 private:
  // Applies stage 2 to the pairs (i, j) and (k, l) and records a resulting cycle.
  void tryPairOfPairs(const std::vector<LineSegment>& lines, std::size_t i, std::size_t j, std::size_t k, std::size_t l,
                      std::vector<SideCycle>& cycles) const;

  GroupingParams params_;
};

// The hypotheses of `quadrangles` not covered by more than maxOverlapRatio of their area by a
// larger kept one (so never one contained in another), largest first. Throws
// InvalidArgumentError unless maxOverlapRatio lies in [0, 1).
std::vector<Quadrangle> removeContainedAndOverlapping(const std::vector<Quadrangle>& quadrangles,
                                                      double maxOverlapRatio);

}  // namespace rgnav
