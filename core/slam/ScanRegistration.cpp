// Correlative search, then refinement, then the inlier test.
#include "core/slam/ScanRegistration.h"

#include <algorithm>

#include "core/slam/UndeterminedDirection.h"

namespace rgnav {

std::optional<Registration> registerScan(const ReferenceMap& reference, std::span<const Eigen::Vector2f> query,
                                         const Pose2D& guess, const RegistrationCriteria& criteria,
                                         const IcpConfig& icp, const PosePrior* prior) {
  const auto match =
      correlativeSearch(reference.grid(), reference.pyramid(), query, guess, criteria.window, criteria.minScore);
  if (!match) return std::nullopt;
  const auto refined = refinePointToLine(reference, query, match->pose, icp, prior);
  if (!refined || refined->inlierFraction < criteria.minInlierFraction) return std::nullopt;
  Registration result;
  result.pose = refined->pose;
  result.information = refined->pointInformation;
  if (prior != nullptr) {
    result.information += prior->information;
  } else {
    if (criteria.undetermined) {
      const auto direction =
          undeterminedDirection(reference.grid(), query, result.pose, result.information, *criteria.undetermined);
      if (direction) dropDirection(result.pose, result.information, guess, *direction);
    }
    // The window bounds the pose even where the scan does not (a featureless corridor): a floor
    // that keeps the information positive definite.
    const double resolution = reference.grid().resolution();
    const double translation = std::max(criteria.window.translation, resolution);
    const double rotation = std::max(criteria.window.rotation, resolution);
    result.information += Eigen::Vector3d(1.0 / (translation * translation), 1.0 / (translation * translation),
                                          1.0 / (rotation * rotation))
                              .asDiagonal();
  }
  result.score = match->score;
  result.inlierFraction = refined->inlierFraction;
  return result;
}

}  // namespace rgnav
