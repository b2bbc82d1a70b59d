// LoopCloser: detects revisits (loop closing, in the sense of Gutmann & Konolige 1999 global
// correlation and of Hess et al. 2016 constraint search): the current keyframe is matched
// against the submaps of older keyframes whose anchor lies near its current estimate, with a
// correlative search window that grows with the path travelled since the last loop closure (the
// uncertainty accumulated since), and verified by the correlative score and the inlier fraction
// after point-to-line refinement. Accepted matches become loop constraints anchor -> keyframe.
// Submaps are rigid (their member poses frozen when made, SubmapRecord); their rasterisations are
// kept in a small least-recently-used cache, rebuilt on demand from the state.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <list>
#include <memory>
#include <span>
#include <vector>

#include "core/slam/ReferenceMap.h"
#include "core/slam/ScanRegistration.h"
#include "core/slam/SlamConfig.h"
#include "core/slam/SlamState.h"

namespace rgnav {

class LoopCloser {
 public:
  LoopCloser(const LoopClosureConfig& loop, const IcpConfig& icp);

  // The search window for a keyframe reached after `distanceSinceLoop` metres without a loop.
  SearchWindow window(double distanceSinceLoop) const;

  // Loop constraints for keyframe `current` of `state`; `normals[k]` are the normals of keyframe
  // k's points. Does not change the state.
  std::vector<Constraint> search(const SlamState& state, KeyframeIndex current,
                                 std::span<const std::vector<Eigen::Vector2f>> normals);

 private:
  const ReferenceMap& submapReference(const SlamState& state, std::size_t submap,
                                      std::span<const std::vector<Eigen::Vector2f>> normals);

  LoopClosureConfig config_;
  IcpConfig icp_;
  int pyramidLevels_;
  std::list<std::pair<std::size_t, std::unique_ptr<ReferenceMap>>> cache_;  // most recently used first
};

}  // namespace rgnav
