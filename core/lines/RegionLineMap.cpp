// Incremental region line map; see RegionLineMap.h.
#include "core/lines/RegionLineMap.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

// Side of the grid cells. Not a thesis parameter: about the length of a short wall segment, so
// that a cell holds few lines and a segment touches few cells.
constexpr double kGridCellM = 1.0;

}  // namespace

RegionLineMap::RegionLineMap(const LineExtractorParams& extractor, const LineMergerParams& merger)
    : extractor_(extractor), merger_(merger), grid_(kGridCellM, mergeReach(merger)) {}

void RegionLineMap::addScan(const LaserScan& scan, const Pose2D& sensorPose) {
  // Checked before anything changes: a non-finite pose gives non-finite lines.
  if (!std::isfinite(sensorPose.x) || !std::isfinite(sensorPose.y) || !std::isfinite(sensorPose.theta))
    throw InvalidArgumentError("region line map: scan " + std::to_string(scan.id) + " has a non-finite sensor pose");
  const std::vector<ScanPoint> points = scanPoints(scan, sensorPose);
  std::vector<LineSegment> fresh = extractor_.extract(points, scan.angleIncrement, nextId_);
  ++scans_;
  points_ += points.size();
  nextId_ += fresh.size();

  std::vector<Key> gone;                // published lines merged away
  std::vector<LineGrid::Handle> added;  // lines made by this scan, still in the map
  for (LineSegment& segment : fresh) {
    LineSegment line = std::move(segment);
    for (bool grew = true; grew;) {
      grew = false;
      for (const LineGrid::Handle other : grid_.near(line)) {
        ++candidates_;
        auto merged = merger_.tryMerge(line, grid_.line(other));
        if (!merged) continue;
        if (const auto it = std::find(added.begin(), added.end(), other); it != added.end())
          added.erase(it);
        else
          gone.push_back(key(other));
        grid_.remove(other);
        line = std::move(*merged);
        grew = true;
      }
    }
    added.push_back(grid_.insert(std::move(line)));
  }
  publish(std::move(gone), added);
}

void RegionLineMap::publish(std::vector<Key> gone, const std::vector<LineGrid::Handle>& added) {
  if (gone.empty() && added.empty()) return;
  std::vector<std::pair<Key, LineGrid::Handle>> fresh;
  for (const LineGrid::Handle h : added) fresh.emplace_back(key(h), h);
  std::sort(fresh.begin(), fresh.end());
  std::sort(gone.begin(), gone.end());

  // One pass merging the kept lines (moved) with the new ones (copied), both in key order.
  std::vector<LineSegment> lines;
  std::vector<Key> keys;
  lines.reserve(lines_.size() + fresh.size() - gone.size());
  keys.reserve(lines.capacity());
  auto freshIt = fresh.begin();
  const auto addFreshBefore = [&](const Key* limit) {
    for (; freshIt != fresh.end() && (limit == nullptr || freshIt->first < *limit); ++freshIt) {
      keys.push_back(freshIt->first);
      lines.push_back(grid_.line(freshIt->second));
    }
  };
  auto goneIt = gone.begin();
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    addFreshBefore(&keys_[i]);
    if (goneIt != gone.end() && *goneIt == keys_[i]) {
      ++goneIt;
      continue;
    }
    keys.push_back(keys_[i]);
    lines.push_back(std::move(lines_[i]));
  }
  addFreshBefore(nullptr);
  lines_ = std::move(lines);
  keys_ = std::move(keys);
}

}  // namespace rgnav
