// undeterminedDirection: whether a scan registered without a pose prior (a loop closure)
// determines its position in every direction. In a corridor the point-to-line information along
// the axis comes from the noise of the estimated normals rather than from structure, so it
// overstates what the scan says, and the refined position along the axis is arbitrary: such
// revisits pulled whole corridors of the simulator's office floors metres out of place. The test
// follows the covariance estimate of Olson 2009 (real-time correlative scan matching: the spread
// of the correlation response around the best pose), reduced to the least-constrained direction
// of the point information and two probes along it; it also requires the point information
// along it to be weak, since a short feature can constrain a pose that a 0.2 m shift does not
// reveal. dropDirection then keeps only what the scan determines.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>

#include "core/common/Pose2D.h"
#include "core/slam/PointGrid.h"
#include "core/slam/SlamConfig.h"

namespace rgnav {

// The unit direction (grid frame) along which `query` (sensor frame) placed at `pose` in `grid`
// does not determine the position, or nullopt. `pointInformation` (x, y, theta) is the scan
// points' information about `pose`; its weakest translational eigenvector is the candidate.
std::optional<Eigen::Vector2d> undeterminedDirection(const PointGrid& grid, std::span<const Eigen::Vector2f> query,
                                                     const Pose2D& pose, const Eigen::Matrix3d& pointInformation,
                                                     const UndeterminedDirectionConfig& config);

// Moves `pose` along the unit `direction` to the position of `guess` along it, and removes all
// information about the position along it (leaving `information` singular in that direction).
void dropDirection(Pose2D& pose, Eigen::Matrix3d& information, const Pose2D& guess, const Eigen::Vector2d& direction);

}  // namespace rgnav
