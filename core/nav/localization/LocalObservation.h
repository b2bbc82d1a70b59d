// LocalObservation: what the robot has seen lately, for recognising the region it is in (global
// localization, RegionRecognition.h): the scans of the last few metres of travel, placed at their
// raw odometry poses relative to the newest scan (the "local frame": the robot at the origin,
// heading along x). Odometry drifts little over a few metres, so the scans form a local map good
// enough to compare with a mapped region; it is not corrected (no scan matching), which keeps it
// independent of the map it is compared with.
// From it come the beam end points, the 15 cm freespace of those scans (RegionFreespace, as a
// mapped region's) and the line segments of each scan (LineExtractor), for the main directions.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <deque>
#include <vector>

#include "core/common/SensorData.h"
#include "core/lines/LineSegment.h"
#include "core/rgmap/describe/RegionFreespace.h"

namespace rgnav {

struct LocalObservationConfig {
  double historyTravelM = 6.0;   // scans older than this much odometry travel are dropped
  std::size_t maxScans = 200;    // and never more than this many
  std::size_t lineScanStride = 5;  // every n-th scan gives line segments (they overlap heavily)
};

struct LocalObservation {
  std::vector<Eigen::Vector2d> points;  // end points of beams with a return, local frame
  RegionFreespace freespace;            // 15 cm (FreespaceConfig defaults), local frame
  std::vector<LineSegment> lines;       // local frame
  double travelM = 0.0;                 // odometry travel the scans span
  std::size_t scans = 0;
};

class RecentScans {
 public:
  explicit RecentScans(const LocalObservationConfig& config = {}) : config_(config) {}

  // Adds the newest scan (by its LaserScan::odometry) and drops what is too old.
  void add(const LaserScan& scan);
  // Keeps only the newest scan (after a detected kidnapping the older ones are of another place).
  void keepNewest();
  void clear() { scans_.clear(); }

  std::size_t size() const { return scans_.size(); }
  const LaserScan& newest() const;  // NotAvailableError if empty
  double travelM() const;  // odometry travel from the oldest to the newest scan
  // The observation in the frame of the newest scan: of all scans held, or of the newest ones
  // whose odometry travel spans at most maxTravelM (at least the newest). NotAvailableError if empty.
  LocalObservation observation() const;
  LocalObservation observation(double maxTravelM) const;

 private:
  LocalObservationConfig config_;
  std::deque<LaserScan> scans_;
  std::deque<double> travelTo_;  // odometry travel from the previous scan to this one
};

}  // namespace rgnav
