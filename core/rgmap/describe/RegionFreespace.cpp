// Incrementally grown freespace grid of a region; see RegionFreespace.h.
#include "core/rgmap/describe/RegionFreespace.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "core/common/Errors.h"
#include "core/lines/ScanPoints.h"

namespace rgnav {
namespace {

constexpr int kMaxCellsPerSide = 10000;
constexpr double kGrowthMarginM = 2.0;  // at least this much room is added when the grid grows
constexpr double kFarCells = 1e9;       // lattice coordinates beyond this are rejected outright
constexpr double kInsideBorder = 1e-6;  // cells: beams cut at the window's border end this far inside

void validate(const FreespaceConfig& c) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  const auto nonNegative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!positive(c.cellSizeM) || !positive(c.maxExtentM))
    throw ConfigError("region freespace: cellSizeM and maxExtentM must be positive");
  if (!nonNegative(c.noReturnFreeRangeM) || !nonNegative(c.freePerHit))
    throw ConfigError("region freespace: noReturnFreeRangeM and freePerHit must be >= 0");
  if (c.maxExtentM / c.cellSizeM > kMaxCellsPerSide || c.maxExtentM < c.cellSizeM)
    throw ConfigError("region freespace: maxExtentM must hold between 1 and " + std::to_string(kMaxCellsPerSide) +
                      " cells per side");
}

// One axis of a growing window: the span [lo, hi] that covers the current span [cur0, cur1]
// (none if `empty`) and [needLo, needHi], with `margin` cells added on each side that had to
// grow, trimmed back to maxCells. Where that cannot be covered in maxCells, the span of maxCells
// that keeps the current span and [keepLo, keepHi] and reaches as far towards the needed ends as
// it can (no margin); none if even those do not fit.
struct Span {
  int lo, hi;
};
std::optional<Span> grownSpan(int needLo, int needHi, int keepLo, int keepHi, int cur0, int cur1, bool empty,
                              int margin, int maxCells) {
  const int coreLo = empty ? needLo : std::min(needLo, cur0);
  const int coreHi = empty ? needHi : std::max(needHi, cur1);
  if (coreHi - coreLo + 1 > maxCells) {
    const int fixedLo = empty ? keepLo : std::min(keepLo, cur0), fixedHi = empty ? keepHi : std::max(keepHi, cur1);
    const int spare = maxCells - (fixedHi - fixedLo + 1);
    if (spare < 0) return std::nullopt;
    const int wantLo = fixedLo - coreLo, wantHi = coreHi - fixedHi;
    const int giveLo = std::min(wantLo, std::max(spare / 2, spare - wantHi));
    return Span{fixedLo - giveLo, fixedHi + std::min(wantHi, spare - giveLo)};
  }
  int lo = (empty || needLo < cur0) ? coreLo - margin : coreLo;
  int hi = (empty || needHi > cur1) ? coreHi + margin : coreHi;
  int excess = hi - lo + 1 - maxCells;
  if (excess > 0) {
    const int trimHi = std::min(excess, hi - coreHi);
    hi -= trimHi;
    lo += excess - trimHi;
  }
  return Span{lo, hi};
}

// Where the segment from `a`, inside the box [lo, hi], to `b` leaves the box: the parameter t in
// (0, 1] along it (1 if it stays inside).
double exitParameter(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& lo,
                     const Eigen::Vector2d& hi) {
  double t = 1.0;
  const Eigen::Vector2d d = b - a;
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] > 0.0) t = std::min(t, (hi[axis] - a[axis]) / d[axis]);
    if (d[axis] < 0.0) t = std::min(t, (lo[axis] - a[axis]) / d[axis]);
  }
  return t;
}

}  // namespace

RegionFreespace::RegionFreespace(const FreespaceConfig& config) : config_(config) {
  validate(config_);
  maxCells_ = int(std::floor(config_.maxExtentM / config_.cellSizeM));
}

bool RegionFreespace::addScan(const LaserScan& scan, const Pose2D& sensorPose,
                              std::span<const GatewaySegment> gateways) {
  return addBeams(regionBeams(scan, sensorPose, gateways, config_.noReturnFreeRangeM));
}

bool RegionFreespace::addBeams(const RegionBeams& beams) {
  if (!beams.origin.allFinite()) throw InvalidArgumentError("region freespace: the sensor position must be finite");
  const double perCell = 1.0 / config_.cellSizeM;
  Eigen::Vector2d lo = beams.origin * perCell, hi = lo;
  for (const RegionBeam& b : beams.beams) {
    if (!b.end.allFinite()) throw InvalidArgumentError("region freespace: beam ends must be finite");
    lo = lo.cwiseMin(b.end * perCell);
    hi = hi.cwiseMax(b.end * perCell);
  }
  const Eigen::Vector2d origin = beams.origin * perCell;
  if (!ensureCovers(lo, hi, origin, origin)) return false;

  // Lattice coordinates relative to the window, so that floor() gives the index into counts_;
  // beams are cut at the window's border (just inside it) where the region outgrew maxExtentM.
  // The window holds the sensor's cell with a cell around it, so every beam starts inside.
  const Eigen::Vector2d shift(window_.col0, window_.row0);
  const Eigen::Vector2d boxLo = Eigen::Vector2d::Constant(kInsideBorder);
  const Eigen::Vector2d boxHi = Eigen::Vector2d(window_.width, window_.height).array() - kInsideBorder;
  const Eigen::Vector2d from = origin - shift;
  Counts* cells = counts_.data();
  const std::size_t width = std::size_t(window_.width);
  const auto markFree = [cells, width](int i, int j) { ++cells[std::size_t(j) * width + std::size_t(i)].free; };
  for (const RegionBeam& b : beams.beams) {
    Eigen::Vector2d to = b.end * perCell - shift;
    const double exit = exitParameter(from, to, boxLo, boxHi);
    const bool cut = exit < 1.0;
    if (cut) to = from + exit * (to - from);
    const LatticeCell last = traverseCells(from.x(), from.y(), to.x(), to.y(), markFree);
    Counts& end = cells[std::size_t(last.j) * width + std::size_t(last.i)];
    ++(b.hit && !cut ? end.hit : end.free);
  }
  ++scans_;
  return true;
}

void RegionFreespace::mergeFrom(const RegionFreespace& other, const Pose2D& otherInThis) {
  if (&other == this) throw InvalidArgumentError("region freespace: cannot merge a region with itself");
  if (!std::isfinite(otherInThis.x) || !std::isfinite(otherInThis.y) || !std::isfinite(otherInThis.theta))
    throw InvalidArgumentError("region freespace: merge pose must be finite");
  if (other.window_.empty()) {
    scans_ += other.scans_;
    return;
  }

  // The other window's corners in this lattice.
  const CellWindow& w = other.window_;
  const double s = other.cellSizeM(), perCell = 1.0 / cellSizeM();
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(kFarCells), hi = -lo;
  for (const int ci : {w.col0, w.col0 + w.width})
    for (const int cj : {w.row0, w.row0 + w.height}) {
      const Eigen::Vector2d corner = transformPoint(otherInThis, Eigen::Vector2d(ci * s, cj * s)) * perCell;
      lo = lo.cwiseMin(corner);
      hi = hi.cwiseMax(corner);
    }
  // The two together may outgrow maxExtentM: this grid then keeps what it holds and takes as
  // much of the other's as fits (around the other's centre if this one is empty).
  const Eigen::Vector2d keep = window_.empty() ? Eigen::Vector2d(0.5 * (lo + hi))
                                              : Eigen::Vector2d(window_.col0 + 0.5 * window_.width,
                                                                window_.row0 + 0.5 * window_.height);
  ensureCovers(lo, hi, keep, keep);
  scans_ += other.scans_;

  // Every cell of ours under the other grid samples the other cell under its centre (as far as
  // this grid reaches, where the two together outgrow maxExtentM).
  const Pose2D thisInOther = inverse(otherInThis);
  const int j0 = std::max(int(std::floor(lo.y())), window_.row0);
  const int j1 = std::min(int(std::floor(hi.y())), window_.row0 + window_.height - 1);
  const int i0 = std::max(int(std::floor(lo.x())), window_.col0);
  const int i1 = std::min(int(std::floor(hi.x())), window_.col0 + window_.width - 1);
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const LatticeCell source = other.cellOf(transformPoint(thisInOther, cellCenter(i, j)));
      if (!w.contains(source.i, source.j)) continue;
      const Counts& add = other.at(source.i, source.j);
      Counts& mine = at(i, j);
      mine.free += add.free;
      mine.hit += add.hit;
    }
}

FreespaceCell RegionFreespace::cell(int i, int j) const {
  return window_.contains(i, j) ? state(at(i, j)) : FreespaceCell::Unknown;
}

LatticeCell RegionFreespace::cellOf(const Eigen::Vector2d& point) const {
  return {int(std::floor(point.x() / config_.cellSizeM)), int(std::floor(point.y() / config_.cellSizeM))};
}

Eigen::Vector2d RegionFreespace::cellCenter(int i, int j) const {
  return config_.cellSizeM * Eigen::Vector2d(i + 0.5, j + 0.5);
}

FreespaceBitmap RegionFreespace::bitmap() const {
  int iMin = window_.col0 + window_.width, iMax = window_.col0 - 1;
  int jMin = window_.row0 + window_.height, jMax = window_.row0 - 1;
  for (int j = window_.row0; j < window_.row0 + window_.height; ++j)
    for (int i = window_.col0; i < window_.col0 + window_.width; ++i)
      if (state(at(i, j)) == FreespaceCell::Free) {
        iMin = std::min(iMin, i);
        iMax = std::max(iMax, i);
        jMin = std::min(jMin, j);
        jMax = std::max(jMax, j);
      }
  if (iMax < iMin) return FreespaceBitmap::allOccupied(config_.cellSizeM, Eigen::Vector2d::Zero(), 0, 0);
  FreespaceBitmap map = FreespaceBitmap::allOccupied(
      config_.cellSizeM, config_.cellSizeM * Eigen::Vector2d(iMin, jMin), iMax - iMin + 1, jMax - jMin + 1);
  for (int j = jMin; j <= jMax; ++j)
    for (int i = iMin; i <= iMax; ++i)
      if (state(at(i, j)) == FreespaceCell::Free) map.setFree(i - iMin, j - jMin);
  return map;
}

FreespaceCell RegionFreespace::state(const Counts& c) const {
  if (c.free == 0 && c.hit == 0) return FreespaceCell::Unknown;
  return c.free > 0 && double(c.free) >= config_.freePerHit * double(c.hit) ? FreespaceCell::Free
                                                                          : FreespaceCell::Occupied;
}

bool RegionFreespace::ensureCovers(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const Eigen::Vector2d& keepLo,
                                   const Eigen::Vector2d& keepHi) {
  if (!lo.allFinite() || !hi.allFinite() || lo.minCoeff() < -kFarCells || hi.maxCoeff() > kFarCells)
    throw InvalidArgumentError("region freespace: beams must be finite and within 1e9 cells");
  // One cell more on each side than needed absorbs any rounding of the shifted coordinates.
  const int needI0 = int(std::floor(lo.x())) - 1, needI1 = int(std::floor(hi.x())) + 1;
  const int needJ0 = int(std::floor(lo.y())) - 1, needJ1 = int(std::floor(hi.y())) + 1;
  const CellWindow& w = window_;
  if (!w.empty() && w.contains(needI0, needJ0) && w.contains(needI1, needJ1)) return true;

  const int margin = int(std::ceil(kGrowthMarginM / config_.cellSizeM));
  // Growing by half the current size as well keeps the copying linear in the final size.
  const std::optional<Span> cols =
      grownSpan(needI0, needI1, int(std::floor(keepLo.x())) - 1, int(std::floor(keepHi.x())) + 1, w.col0,
                w.col0 + w.width - 1, w.empty(), std::max(margin, w.width / 2), maxCells_);
  const std::optional<Span> rows =
      grownSpan(needJ0, needJ1, int(std::floor(keepLo.y())) - 1, int(std::floor(keepHi.y())) + 1, w.row0,
                w.row0 + w.height - 1, w.empty(), std::max(margin, w.height / 2), maxCells_);
  if (!cols || !rows) return false;
  const CellWindow grown{cols->lo, rows->lo, cols->hi - cols->lo + 1, rows->hi - rows->lo + 1};
  if (grown == w) return true;  // at its largest already: beams get cut, nothing to copy
  std::vector<Counts> counts(std::size_t(grown.width) * std::size_t(grown.height));
  for (int j = w.row0; j < w.row0 + w.height; ++j)
    std::copy_n(&at(w.col0, j), w.width,
                &counts[std::size_t(j - grown.row0) * std::size_t(grown.width) + std::size_t(w.col0 - grown.col0)]);
  window_ = grown;
  counts_ = std::move(counts);
  return true;
}

}  // namespace rgnav
