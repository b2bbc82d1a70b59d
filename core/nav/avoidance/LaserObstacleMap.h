// LaserObstacleMap: the laser's ObstacleGrid for the Collision Avoidance (thesis 5.5.3: the CAM
// reasons on the latest sensor data): a log-odds occupancy grid in the odometry frame around the
// robot, built from laser scans at their odometry poses. Each scan lowers the log-odds of every
// cell its beams pass through (cv::line into a per-scan mask, so a cell counts once per scan)
// and raises those its beams end in, both clamped, so a person's trail is cleared within a few
// scans while a static obstacle stays. The grid scrolls in whole cells to keep the robot away from
// its border. An obstacle in a cell that beams passed well short of their ends within
// movingMemoryS, in a group of such cells that lies next to no obstacle seen free longer ago, is a
// moving one (a person walking into free space; a wall's face is only passed by beams about to end
// on it); once seen, it is followed through the cells occupied for less than movingMemoryS next to
// cells it has left (a person walking away shows only cells it hid before): the moving layer. Unlike the
// thesis' 3D stereo fusion (5.5.3) there is one sensor.
#pragma once

#include <opencv2/core.hpp>

#include "core/common/SensorData.h"
#include "core/nav/avoidance/ObstacleGrid.h"

namespace rgnav {

struct LaserObstacleMapConfig {
  double resolutionM = 0.05;
  double sizeM = 20.0;              // side of the square grid
  double recenterMarginM = 5.0;     // scroll when the laser comes this close to the border
  double laserForwardOffsetM = 0.0; // laser ahead of the robot's rotation centre
  double maxClearRangeM = 8.0;      // beams clear free space up to here
  double hitLogOdds = 0.85;
  double missLogOdds = -0.4;
  double clampLogOdds = 2.0;        // log-odds stay within +-this
  double occupiedLogOdds = 0.5;     // above: Occupied
  double freeLogOdds = -0.3;        // below: Free; between: Unknown
  double movingMemoryS = 2.0;       // an obstacle in a cell seen Free this recently moves
};

// Throws ConfigError naming the first bad value.
void validate(const LaserObstacleMapConfig& config);

class LaserObstacleMap {
 public:
  explicit LaserObstacleMap(const LaserObstacleMapConfig& config);

  // Adds one scan (its odometry pose, angles and ranges); the first scan centres the grid.
  void add(const LaserScan& scan);
  // The cells as they stand after the latest scan (empty grid before the first).
  ObstacleGrid grid() const;

 private:
  void centreOn(WorldPoint p);
  void findMoving();  // the moving layer after a scan
  bool occupiedAt(int row, int col) const;
  static cv::Mat shifted(const cv::Mat& grid, int dx, int dy, double fill);
  cv::Point cellOf(double x, double y) const;

  LaserObstacleMapConfig config_;
  cv::Mat logOdds_;  // CV_32F, row 0 = lowest y
  cv::Mat mask_;     // CV_8U per scan: 1 passed, 2 hit
  cv::Mat evidence_; // CV_8U per scan: 1 passed well short of the beam's end
  cv::Mat seenFree_; // CV_64F: the stamp of the last scan after which the cell was Free
  cv::Mat occupiedSince_;  // CV_64F: since when the cell is Occupied (infinite: it is not)
  cv::Mat movedAt_;        // CV_64F: the last scan that found a moving obstacle in the cell
  cv::Mat moving_;         // CV_8U: the moving layer after the latest scan
  WorldPoint origin_;
  Timestamp stamp_ = 0.0;
  bool started_ = false;
};

}  // namespace rgnav
