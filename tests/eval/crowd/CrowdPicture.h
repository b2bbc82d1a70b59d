// CrowdPicture: the picture of a crowd evaluation run, to see where the robot drove and where it
// failed: the world's occupancy grid at about 40 px per metre, north (+y) at the top; each goal's
// true driven path as a polyline in the goal's colour (a palette, cycled), the goal as a dot of
// that colour with its number beside it; a goal not reached ringed in red, with a red cross where
// the robot ended; the start pose as a black ring with a heading line. People are not drawn (the
// run does not record them).
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>

#include "core/common/Pose2D.h"
#include "core/raster/OccupancyGrid.h"
#include "tests/eval/crowd/CrowdRun.h"

namespace rgnav {

// The colour (BGR) of goal `index` (0-based), its path and its dot; never the failure red.
cv::Scalar crowdGoalColour(std::size_t index);
// The colour (BGR) of what failed: the ring around a goal not reached and the cross where it ended.
cv::Scalar crowdFailureColour();
// Where the world point `p` lands in the picture of `grid`.
cv::Point crowdPicturePixel(const OccupancyGrid& grid, const Eigen::Vector2d& p);

// Writes the picture as a PNG (`path` ends in .png); InvalidArgumentError for another ending,
// FileError when the file cannot be written (both name the path).
void writeCrowdPicture(const std::string& path, const OccupancyGrid& grid, const Pose2D& start,
                       const CrowdOutcome& outcome);

}  // namespace rgnav
