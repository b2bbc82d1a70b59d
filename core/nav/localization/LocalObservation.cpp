// The scans of the last metres of travel as a local map (see LocalObservation.h).
#include "core/nav/localization/LocalObservation.h"

#include <cmath>
#include <limits>
#include <numeric>

#include "core/common/Errors.h"
#include "core/lines/LineExtractor.h"
#include "core/lines/ScanPoints.h"

namespace rgnav {

void RecentScans::add(const LaserScan& scan) {
  const double step = scans_.empty() ? 0.0
                                     : std::hypot(scan.odometry.x - scans_.back().odometry.x,
                                                  scan.odometry.y - scans_.back().odometry.y);
  scans_.push_back(scan);
  travelTo_.push_back(step);
  while (scans_.size() > config_.maxScans || (scans_.size() > 1 && travelM() - travelTo_[1] > config_.historyTravelM)) {
    scans_.pop_front();
    travelTo_.pop_front();
  }
}

void RecentScans::keepNewest() {
  while (scans_.size() > 1) {
    scans_.pop_front();
    travelTo_.pop_front();
  }
}

const LaserScan& RecentScans::newest() const {
  if (scans_.empty()) throw NotAvailableError("RecentScans: no scan yet");
  return scans_.back();
}

double RecentScans::travelM() const {
  // The first scan's step leads from a scan already dropped.
  return travelTo_.empty() ? 0.0 : std::accumulate(travelTo_.begin() + 1, travelTo_.end(), 0.0);
}

LocalObservation RecentScans::observation() const { return observation(std::numeric_limits<double>::infinity()); }

LocalObservation RecentScans::observation(double maxTravelM) const {
  if (scans_.empty()) throw NotAvailableError("RecentScans: no scan yet");
  std::size_t first = scans_.size() - 1;
  for (double travel = 0.0; first > 0 && travel + travelTo_[first] <= maxTravelM; --first) travel += travelTo_[first];
  LocalObservation out;
  const Pose2D newest = scans_.back().odometry;
  const LineExtractor extractor;
  SegmentId nextSegment = 1;
  for (std::size_t i = first; i < scans_.size(); ++i) {
    const LaserScan& scan = scans_[i];
    const Pose2D pose = between(newest, scan.odometry);
    for (const ScanPoint& p : scanPoints(scan, pose)) out.points.push_back(p.position);
    out.freespace.addScan(scan, pose, {});
    if ((scans_.size() - 1 - i) % config_.lineScanStride == 0) {
      std::vector<LineSegment> lines = extractor.extract(scan, pose, nextSegment);
      nextSegment += lines.size();
      out.lines.insert(out.lines.end(), std::make_move_iterator(lines.begin()), std::make_move_iterator(lines.end()));
    }
  }
  out.travelM = std::accumulate(travelTo_.begin() + std::ptrdiff_t(first) + 1, travelTo_.end(), 0.0);
  out.scans = scans_.size() - first;
  return out;
}

}  // namespace rgnav
