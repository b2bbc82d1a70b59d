// Incremental region line map; see RegionLineMap.h.
#include "core/lines/RegionLineMap.h"

namespace rgnav {

RegionLineMap::RegionLineMap(const LineExtractorParams& extractor, const LineMergerParams& merger)
    : extractor_(extractor), merger_(merger) {}

void RegionLineMap::addScan(const LaserScan& scan, const Pose2D& sensorPose) {
  const std::vector<ScanPoint> points = scanPoints(scan, sensorPose);
  std::vector<LineSegment> fresh = extractor_.extract(points, scan.angleIncrement, nextId_);
  ++scans_;
  points_ += points.size();
  nextId_ += fresh.size();
  std::vector<LineSegment> all = std::move(lines_);
  all.insert(all.end(), std::make_move_iterator(fresh.begin()), std::make_move_iterator(fresh.end()));
  lines_ = merger_.merge(std::move(all));
}

}  // namespace rgnav
