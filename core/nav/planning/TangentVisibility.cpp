// TangentVisibility: convex corners and the loose row scan that proposes tangent edges (see the
// header).
#include "core/nav/planning/TangentVisibility.h"

#include <algorithm>
#include <cmath>

#include "core/nav/planning/SegmentVisibility.h"

namespace rgnav {

namespace {

// Widening of every scan bound: far above the rounding of the interval arithmetic (~1e-13 on
// 512-cell maps), far below the spacing of distinct ray crossings of lattice points.
constexpr double kSlack = 1e-7;

}  // namespace

TangentVisibility::TangentVisibility(const OccupancyGrid& grid)
    : grid_(grid), width_(grid.width()), height_(grid.height()) {
  idAt_.assign(static_cast<std::size_t>(width_ + 1) * static_cast<std::size_t>(height_ + 1), -1);
  lineCorners_.resize(static_cast<std::size_t>(height_ + 1));
  for (int y = 0; y <= height_; ++y) {
    for (int x = 0; x <= width_; ++x) {
      const bool sw = blocked(x - 1, y - 1), se = blocked(x, y - 1), nw = blocked(x - 1, y), ne = blocked(x, y);
      if (sw + se + nw + ne != 1) continue;
      const int id = static_cast<int>(vertices_.size());
      vertices_.emplace_back(x, y);
      wraps_.emplace_back((se || ne) ? 1 : -1, (nw || ne) ? 1 : -1);
      idAt_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_ + 1) + static_cast<std::size_t>(x)] = id;
      lineCorners_[static_cast<std::size_t>(y)].push_back(id);
    }
  }
  runs_.resize(static_cast<std::size_t>(height_));
  for (int row = 0; row < height_; ++row) {
    for (int col = 0; col < width_;) {
      if (blocked(col, row)) {
        ++col;
        continue;
      }
      const int first = col;
      while (col < width_ && !blocked(col, row)) ++col;
      runs_[static_cast<std::size_t>(row)].emplace_back(first, col - 1);
    }
  }
  stamp_.assign(vertices_.size(), 0);
}

bool TangentVisibility::blocked(int col, int row) const { return grid_.blocked(CellIndex{col, row}); }

bool TangentVisibility::tangentAt(int id, const Eigen::Vector2d& d) const {
  const Eigen::Vector2i& q = wrap(id);
  return d.x() * d.y() * q.x() * q.y() <= 0.0;
}

void TangentVisibility::seenTangentCorners(const Eigen::Vector2d& p, int from, std::vector<int>& out) const {
  out.clear();
  proposed_.clear();
  if (++currentStamp_ == 0) {
    std::fill(stamp_.begin(), stamp_.end(), 0);
    currentStamp_ = 1;
  }
  if (from >= 0) stamp_[static_cast<std::size_t>(from)] = currentStamp_;
  // Rays leaving a corner upwards or downwards are tangent on one side of it only.
  double upLo = -1e300, upHi = 1e300, downLo = -1e300, downHi = 1e300;
  if (from >= 0) {
    const bool diagonal = wrap(from).x() * wrap(from).y() > 0;  // blocked cell NE or SW: tangent rays go NW / SE
    (diagonal ? upHi : upLo) = p.x();
    (diagonal ? downLo : downHi) = p.x();
  }
  scanRows(p, +1, upLo, upHi);
  scanRows(p, -1, downLo, downHi);
  if (p.y() == std::floor(p.y())) {
    walkLine(p, +1);
    walkLine(p, -1);
  }
  for (int id : proposed_) {
    const Eigen::Vector2d w = vertex(id).cast<double>();
    const Eigen::Vector2d d = w - p;
    if (!tangentAt(id, d)) continue;
    if (from >= 0 && !tangentAt(from, d)) continue;
    if (segmentFree(grid_, p, w)) out.push_back(id);
  }
}

void TangentVisibility::scanRows(const Eigen::Vector2d& p, int step, double lo, double hi) const {
  const double px = p.x(), py = p.y();
  const int firstRow = step > 0 ? static_cast<int>(std::floor(py)) : static_cast<int>(std::ceil(py)) - 1;
  if (firstRow < 0 || firstRow >= height_) return;
  // From p, the first row is seen wherever its run of free cells containing p reaches.
  for (const auto& [first, last] : runs_[static_cast<std::size_t>(firstRow)]) {
    if (first > px || last + 1 < px) continue;
    const double a = std::max<double>(first, lo), b = std::min<double>(last + 1, hi);
    if (a <= b) stack_.push_back({step > 0 ? firstRow + 1 : firstRow, a, b});
  }
  while (!stack_.empty()) {
    const Interval in = stack_.back();
    stack_.pop_back();
    propose(in.line, in.lo, in.hi);
    const int row = step > 0 ? in.line : in.line - 1;
    if (row < 0 || row >= height_) continue;
    // A ray crossing the line at x crosses the next line at px + (x - px) * k.
    const double k = (in.line + step - py) / (in.line - py);
    const auto project = [&](double x) { return px + (x - px) * k; };
    const double spanLo = std::min(in.lo, project(in.lo)) - kSlack;
    const double spanHi = std::max(in.hi, project(in.hi)) + kSlack;
    const auto& runs = runs_[static_cast<std::size_t>(row)];
    auto it = std::lower_bound(runs.begin(), runs.end(), spanLo,
                               [](const std::pair<int, int>& run, double x) { return run.second + 1 < x; });
    for (; it != runs.end() && it->first <= spanHi; ++it) {
      // The crossings x whose whole span through the row, from x to project(x), lies in the run.
      const double first = it->first, end = it->second + 1;
      const double lower = first >= px ? first : px + (first - px) / k;
      const double upper = end <= px ? end : px + (end - px) / k;
      const double a = std::max(in.lo, lower - kSlack), b = std::min(in.hi, upper + kSlack);
      if (a <= b) stack_.push_back({in.line + step, project(a), project(b)});
    }
  }
}

void TangentVisibility::walkLine(const Eigen::Vector2d& p, int step) const {
  const int line = static_cast<int>(p.y());
  for (int col = step > 0 ? static_cast<int>(std::floor(p.x())) : static_cast<int>(std::ceil(p.x())) - 1;
       col >= 0 && col < width_ && !(blocked(col, line) && blocked(col, line - 1)); col += step) {
    const int x = step > 0 ? col + 1 : col;
    const int id = idAt_[static_cast<std::size_t>(line) * static_cast<std::size_t>(width_ + 1) + static_cast<std::size_t>(x)];
    if (id >= 0) proposeId(id);
  }
}

void TangentVisibility::propose(int line, double lo, double hi) const {
  const auto& ids = lineCorners_[static_cast<std::size_t>(line)];
  auto it = std::lower_bound(ids.begin(), ids.end(), lo - kSlack,
                             [this](int id, double x) { return vertex(id).x() < x; });
  for (; it != ids.end() && vertex(*it).x() <= hi + kSlack; ++it) proposeId(*it);
}

void TangentVisibility::proposeId(int id) const {
  auto& s = stamp_[static_cast<std::size_t>(id)];
  if (s == currentStamp_) return;
  s = currentStamp_;
  proposed_.push_back(id);
}

}  // namespace rgnav
