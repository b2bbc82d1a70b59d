// The log-odds laser obstacle grid (see LaserObstacleMap.h).
#include "core/nav/avoidance/LaserObstacleMap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "core/common/Errors.h"
#include "core/common/ValueChecks.h"

namespace rgnav {

namespace {
constexpr std::uint8_t kPassed = 1;
constexpr std::uint8_t kHit = 2;
constexpr double kNeverFree = -std::numeric_limits<double>::infinity();
// A beam is evidence that a cell is free (for the moving layer) only this far short of its end: a
// beam grazing a wall passes the cells of the wall's face just before it ends (within 5 cm of the
// face for at most 0.4 m where the wall is within the clearing range of 8 m at 1 m distance).
constexpr double kFreeEvidenceShortM = 0.5;
// A moving obstacle, once seen, is followed: the young obstacle cells (occupied for less than the
// memory) within this distance of cells it has left within kFollowS (moving then, seen free since
// by beams well short of their ends) move too (a person walking away shows only cells it hid before, which were never seen free; a wall
// taken for moving leaves no cell).
constexpr double kFollowM = 0.3;
constexpr double kFollowS = 0.3;
constexpr double kNotOccupied = std::numeric_limits<double>::infinity();
// A moving obstacle shows at least this many fresh cells (a person, 0.5 m across, some ten at 5 cm
// nearby; single ones are corners and door jambs that beams passed close by).
constexpr int kMinMovingCells = 2;
}  // namespace

void validate(const LaserObstacleMapConfig& c) {
  const auto positive = [](double v, const char* name) { requirePositive(v, std::string("laser obstacle map: ") + name); };
  positive(c.resolutionM, "resolution_m");
  positive(c.sizeM, "size_m");
  positive(c.maxClearRangeM, "max_clear_range_m");
  positive(c.hitLogOdds, "hit_log_odds");
  positive(c.clampLogOdds, "clamp_log_odds");
  positive(c.occupiedLogOdds, "occupied_log_odds");
  positive(c.movingMemoryS, "moving_memory_s");
  if (!(c.missLogOdds < 0.0)) throw ConfigError("laser obstacle map: miss_log_odds must be negative");
  if (!(c.freeLogOdds < 0.0)) throw ConfigError("laser obstacle map: free_log_odds must be negative");
  if (!(c.recenterMarginM >= 0.0) || c.recenterMarginM >= c.sizeM / 2.0)
    throw ConfigError("laser obstacle map: recenter_margin_m must lie in [0, size_m / 2)");
  if (!std::isfinite(c.laserForwardOffsetM)) throw ConfigError("laser obstacle map: laser_forward_offset_m must be finite");
  if (c.occupiedLogOdds > c.clampLogOdds || -c.freeLogOdds > c.clampLogOdds)
    throw ConfigError("laser obstacle map: the thresholds must lie within clamp_log_odds");
}

LaserObstacleMap::LaserObstacleMap(const LaserObstacleMapConfig& config) : config_((validate(config), config)) {
  const int side = static_cast<int>(std::ceil(config.sizeM / config.resolutionM));
  logOdds_ = cv::Mat::zeros(side, side, CV_32F);
  mask_ = cv::Mat::zeros(side, side, CV_8U);
  evidence_ = cv::Mat::zeros(side, side, CV_8U);
  seenFree_ = cv::Mat(side, side, CV_64F, cv::Scalar(kNeverFree));
  occupiedSince_ = cv::Mat(side, side, CV_64F, cv::Scalar(kNotOccupied));
  movedAt_ = cv::Mat(side, side, CV_64F, cv::Scalar(kNeverFree));
  moving_ = cv::Mat::zeros(side, side, CV_8U);
}

cv::Mat LaserObstacleMap::shifted(const cv::Mat& grid, int dx, int dy, double fill) {
  cv::Mat out(grid.size(), grid.type(), cv::Scalar(fill));
  const int n = grid.cols;
  const int w = n - std::abs(dx), h = n - std::abs(dy);
  if (w > 0 && h > 0) {
    const cv::Rect from(std::max(dx, 0), std::max(dy, 0), w, h);
    const cv::Rect to(std::max(-dx, 0), std::max(-dy, 0), w, h);
    grid(from).copyTo(out(to));
  }
  return out;
}

cv::Point LaserObstacleMap::cellOf(double x, double y) const {
  return {static_cast<int>(std::floor((x - origin_.x) / config_.resolutionM)),
          static_cast<int>(std::floor((y - origin_.y) / config_.resolutionM))};
}

void LaserObstacleMap::centreOn(WorldPoint p) {
  const double half = logOdds_.cols * config_.resolutionM / 2.0;
  if (!started_) {
    origin_ = {p.x - half, p.y - half};
    started_ = true;
    return;
  }
  const double margin = config_.recenterMarginM;
  const double size = logOdds_.cols * config_.resolutionM;
  const double rx = p.x - origin_.x, ry = p.y - origin_.y;
  if (rx >= margin && ry >= margin && rx <= size - margin && ry <= size - margin) return;
  // Shift by whole cells so that kept cells keep their values exactly.
  const int dx = static_cast<int>(std::lround((rx - half) / config_.resolutionM));
  const int dy = static_cast<int>(std::lround((ry - half) / config_.resolutionM));
  logOdds_ = shifted(logOdds_, dx, dy, 0.0);
  seenFree_ = shifted(seenFree_, dx, dy, kNeverFree);
  occupiedSince_ = shifted(occupiedSince_, dx, dy, kNotOccupied);
  movedAt_ = shifted(movedAt_, dx, dy, kNeverFree);
  origin_ = {origin_.x + dx * config_.resolutionM, origin_.y + dy * config_.resolutionM};
}

void LaserObstacleMap::add(const LaserScan& scan) {
  const Pose2D laser = compose(scan.odometry, {config_.laserForwardOffsetM, 0.0, 0.0});
  centreOn({laser.x, laser.y});
  stamp_ = scan.stamp;
  mask_.setTo(0);
  evidence_.setTo(0);
  const cv::Point from = cellOf(laser.x, laser.y);
  const double clearRange = std::min(config_.maxClearRangeM, scan.maxRange > 0.0 ? scan.maxRange : config_.maxClearRangeM);
  const cv::Rect inside(0, 0, mask_.cols, mask_.rows);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const float r = scan.ranges[i];
    if (std::isnan(r)) continue;
    const double angle = laser.theta + scan.startAngle + static_cast<double>(i) * scan.angleIncrement;
    const double c = std::cos(angle), s = std::sin(angle);
    const bool hit = std::isfinite(r) && r < clearRange;
    // A beam clears up to one cell short of its end: a grazing beam must not erase the obstacle.
    const double clear = hit ? std::max(0.0, r - config_.resolutionM) : clearRange;
    cv::line(mask_, from, cellOf(laser.x + c * clear, laser.y + s * clear), cv::Scalar(kPassed));
    const double evident = std::min(clear, (std::isfinite(r) ? r : clearRange) - kFreeEvidenceShortM);
    if (evident > 0.0) cv::line(evidence_, from, cellOf(laser.x + c * evident, laser.y + s * evident), cv::Scalar(1));
    if (hit) {
      const cv::Point end = cellOf(laser.x + c * r, laser.y + s * r);
      if (inside.contains(end)) mask_.at<std::uint8_t>(end) = kHit;
    }
  }
  const auto hitOdds = static_cast<float>(config_.hitLogOdds);
  const auto missOdds = static_cast<float>(config_.missLogOdds);
  const auto clamp = static_cast<float>(config_.clampLogOdds);
  const auto free = static_cast<float>(config_.freeLogOdds);
  for (int row = 0; row < mask_.rows; ++row) {
    const auto* m = mask_.ptr<std::uint8_t>(row);
    auto* l = logOdds_.ptr<float>(row);
    const auto* e = evidence_.ptr<std::uint8_t>(row);
    auto* seen = seenFree_.ptr<double>(row);
    for (int col = 0; col < mask_.cols; ++col) {
      if (m[col] == 0) continue;
      l[col] = std::clamp(l[col] + (m[col] == kHit ? hitOdds : missOdds), -clamp, clamp);
      if (l[col] < free && e[col] && m[col] != kHit) seen[col] = scan.stamp;
    }
  }
  findMoving();
}

bool LaserObstacleMap::occupiedAt(int row, int col) const {
  return logOdds_.at<float>(row, col) > static_cast<float>(config_.occupiedLogOdds) || mask_.at<std::uint8_t>(row, col) == kHit;
}

void LaserObstacleMap::findMoving() {
  const double since = stamp_ - config_.movingMemoryS;
  cv::Mat fresh = cv::Mat::zeros(logOdds_.size(), CV_8U);     // occupied, seen free lately
  cv::Mat standing = cv::Mat::zeros(logOdds_.size(), CV_8U);  // occupied, not seen free lately
  cv::Mat young = cv::Mat::zeros(logOdds_.size(), CV_8U);     // occupied for less than the memory
  cv::Mat vacated = cv::Mat::zeros(logOdds_.size(), CV_8U);   // moving within kFollowS, free now
  for (int row = 0; row < logOdds_.rows; ++row) {
    const auto* seen = seenFree_.ptr<double>(row);
    auto* occupiedSince = occupiedSince_.ptr<double>(row);
    const auto* movedAt = movedAt_.ptr<double>(row);
    for (int col = 0; col < logOdds_.cols; ++col) {
      if (!occupiedAt(row, col)) {
        occupiedSince[col] = kNotOccupied;
        vacated.at<std::uint8_t>(row, col) = movedAt[col] >= stamp_ - kFollowS && seen[col] >= stamp_ - kFollowS;
        continue;
      }
      occupiedSince[col] = std::min(occupiedSince[col], stamp_);
      young.at<std::uint8_t>(row, col) = occupiedSince[col] >= since;
      (seen[col] >= since ? fresh : standing).at<std::uint8_t>(row, col) = 1;
    }
  }
  // A fresh cell beside a standing one is the edge of a wall that grazing beams had cleared, and a
  // fresh cell alone a corner or a door jamb that beams passed close by; a person walking into free
  // space is a group of fresh cells (cells a cell apart count as one group).
  cv::Mat nearStanding;
  cv::dilate(standing, nearStanding, cv::Mat::ones(3, 3, CV_8U));
  fresh.setTo(0, nearStanding);
  cv::Mat grouped, labels;
  cv::dilate(fresh, grouped, cv::Mat::ones(3, 3, CV_8U));
  const int groups = cv::connectedComponents(grouped, labels, 8, CV_32S);
  std::vector<int> members(static_cast<std::size_t>(groups), 0);
  for (int row = 0; row < fresh.rows; ++row)
    for (int col = 0; col < fresh.cols; ++col)
      if (fresh.at<std::uint8_t>(row, col)) ++members[static_cast<std::size_t>(labels.at<int>(row, col))];
  const int reach = static_cast<int>(std::lround(kFollowM / config_.resolutionM));
  cv::Mat followed;
  cv::dilate(vacated, followed, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * reach + 1, 2 * reach + 1}));
  for (int row = 0; row < fresh.rows; ++row)
    for (int col = 0; col < fresh.cols; ++col) {
      const bool seenMoving =
          fresh.at<std::uint8_t>(row, col) && members[static_cast<std::size_t>(labels.at<int>(row, col))] >= kMinMovingCells;
      const bool follows = young.at<std::uint8_t>(row, col) && followed.at<std::uint8_t>(row, col);
      moving_.at<std::uint8_t>(row, col) = seenMoving || follows;
      if (seenMoving || follows) movedAt_.at<double>(row, col) = stamp_;
    }
}

ObstacleGrid LaserObstacleMap::grid() const {
  ObstacleGrid out;
  out.source = "laser";
  out.stamp = stamp_;
  if (!started_) return out;
  out.cells = OccupancyGrid(logOdds_.cols, logOdds_.rows, config_.resolutionM, origin_, Cell::Unknown);
  out.moving = OccupancyGrid(logOdds_.cols, logOdds_.rows, config_.resolutionM, origin_, Cell::Free);
  const auto free = static_cast<float>(config_.freeLogOdds);
  for (int row = 0; row < logOdds_.rows; ++row) {
    const auto* l = logOdds_.ptr<float>(row);
    const auto* moving = moving_.ptr<std::uint8_t>(row);
    for (int col = 0; col < logOdds_.cols; ++col) {
      // The latest scan's hits are obstacles at once: a walking person crosses a cell faster than
      // its log-odds climb from free to occupied.
      if (occupiedAt(row, col)) {
        out.cells.set({col, row}, Cell::Occupied);
        if (moving[col]) out.moving.set({col, row}, Cell::Occupied);
      } else if (l[col] < free) {
        out.cells.set({col, row}, Cell::Free);
      }
    }
  }
  return out;
}

}  // namespace rgnav
