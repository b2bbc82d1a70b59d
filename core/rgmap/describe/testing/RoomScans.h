// Test helpers for region descriptions: the walls of an axis-aligned rectangular room with an
// optional door gap in its east wall, the poses of a walk through it and its scans (ray cast by
// core/lines/testing/SyntheticScan.h: 361 beams over 180 degrees).
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/lines/testing/SyntheticScan.h"

namespace rgnav::testing {

struct Door {
  double lowY = 0.0;   // the gap in the east wall runs from lowY to highY
  double highY = 0.0;
};

// The four walls of `room` (its inner faces), the east one split around `door` if given.
std::vector<Wall> roomWalls(const Eigen::AlignedBox2d& room, std::optional<Door> door = std::nullopt);

// Poses on an nx x ny grid inside `room` shrunk by marginM on every side; headings turn by
// 1.3 rad from pose to pose, so the 180-degree scans look every way.
std::vector<Pose2D> roomPoses(const Eigen::AlignedBox2d& room, double marginM, int nx, int ny);

// Scans of `walls` from `poses` (sensor poses), with range noise and a seed per scan.
std::vector<LaserScan> scansFrom(const std::vector<Wall>& walls, const std::vector<Pose2D>& poses,
                                 double noiseSigmaM = 0.0);

}  // namespace rgnav::testing
