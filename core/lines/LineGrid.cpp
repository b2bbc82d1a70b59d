// Uniform grid over map lines for merge candidates; see LineGrid.h.
#include "core/lines/LineGrid.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

// Slack on the reach (relative, absolute in metres), so that rounding in the merge tests and in
// cutting a segment into pieces cannot hide a candidate.
constexpr double kReachSlack = 1e-6, kReachSlackM = 1e-9;

}  // namespace

double mergeReach(const LineMergerParams& params) { return params.maxGapM + 4.0 * params.maxLineDistanceM; }

LineGrid::LineGrid(double cellM, double reachM)
    : cellM_(cellM), halfReachM_(0.5 * reachM * (1.0 + kReachSlack) + kReachSlackM) {
  if (!(cellM > 0.0 && std::isfinite(cellM)) || !(reachM >= 0.0 && std::isfinite(reachM)))
    throw InvalidArgumentError("line grid: need a finite cell size > 0 and reach >= 0");
}

std::vector<std::uint64_t> LineGrid::cells(const LineSegment& segment) const {
  const Eigen::Vector2d span = segment.end - segment.start;
  const std::size_t pieces = std::max<std::size_t>(1, std::size_t(std::ceil(span.norm() / cellM_)));
  // Cell index of a coordinate; far-out coordinates are clamped and their keys may coincide,
  // which only adds candidates.
  const auto index = [&](double v) { return std::int64_t(std::clamp(std::floor(v / cellM_), -1e15, 1e15)); };
  std::vector<std::uint64_t> keys;
  for (std::size_t i = 0; i < pieces; ++i) {
    const Eigen::Vector2d a = segment.start + span * (double(i) / double(pieces));
    const Eigen::Vector2d b = segment.start + span * (double(i + 1) / double(pieces));
    const Eigen::Vector2d lo = a.cwiseMin(b).array() - halfReachM_, hi = a.cwiseMax(b).array() + halfReachM_;
    for (std::int64_t x = index(lo.x()); x <= index(hi.x()); ++x)
      for (std::int64_t y = index(lo.y()); y <= index(hi.y()); ++y)
        keys.push_back(std::uint64_t(std::uint32_t(x)) << 32 | std::uint32_t(y));
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

LineGrid::Handle LineGrid::insert(LineSegment line) {
  if (!line.start.allFinite() || !line.end.allFinite())
    throw InvalidArgumentError("line grid: line " + std::to_string(line.id) + " has a non-finite endpoint");
  const double orientation = line.orientationRad();
  Handle handle;
  if (free_.empty()) {
    handle = Handle(slots_.size());
    slots_.push_back({std::move(line), orientation});
  } else {
    handle = free_.back();
    free_.pop_back();
    slots_[handle] = {std::move(line), orientation};
  }
  for (const std::uint64_t key : cells(slots_[handle].line)) grid_[key].push_back(handle);
  ++size_;
  return handle;
}

LineSegment LineGrid::remove(Handle handle) {
  for (const std::uint64_t key : cells(slots_[handle].line)) {
    const auto cell = grid_.find(key);
    std::vector<Handle>& handles = cell->second;
    *std::find(handles.begin(), handles.end(), handle) = handles.back();
    handles.pop_back();
    if (handles.empty()) grid_.erase(cell);
  }
  free_.push_back(handle);
  --size_;
  return std::exchange(slots_[handle].line, LineSegment{});
}

std::vector<LineGrid::Handle> LineGrid::near(const LineSegment& segment) const {
  std::vector<Handle> found;
  for (const std::uint64_t key : cells(segment))
    if (const auto cell = grid_.find(key); cell != grid_.end())
      found.insert(found.end(), cell->second.begin(), cell->second.end());
  const auto sweepOrder = [&](Handle a, Handle b) {
    return std::tuple(slots_[a].orientationRad, slots_[a].line.id, a) <
           std::tuple(slots_[b].orientationRad, slots_[b].line.id, b);
  };
  std::sort(found.begin(), found.end(), sweepOrder);
  found.erase(std::unique(found.begin(), found.end()), found.end());
  return found;
}

}  // namespace rgnav
