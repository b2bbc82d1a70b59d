// PurePursuit: stops at sharp corners, windowed projection onto the polyline, lookahead point,
// curvature and speed.
#include "core/nav/grid/PurePursuit.h"

#include <algorithm>

#include "core/common/Errors.h"
#include "core/common/ValueChecks.h"

namespace rgnav {

namespace {

double distance(WorldPoint a, WorldPoint b) { return std::hypot(b.x - a.x, b.y - a.y); }

void requireAngle(double value, const std::string& what) {
  requirePositive(value, what);
  if (value > M_PI) {
    throw ConfigError(what + " must not exceed pi");
  }
}

// Waypoints where the direction of travel turns by more than `cornerAngle` (repeated waypoints
// are skipped), followed by the last waypoint.
std::vector<std::size_t> findStops(const std::vector<WorldPoint>& path, double cornerAngle) {
  std::vector<std::size_t> stops;
  std::size_t previous = 0;  // the last waypoint distinct from the current one
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    std::size_t next = i + 1;
    while (next + 1 < path.size() && distance(path[i], path[next]) == 0.0) ++next;
    if (distance(path[previous], path[i]) == 0.0 || distance(path[i], path[next]) == 0.0) {
      continue;
    }
    const double in = std::atan2(path[i].y - path[previous].y, path[i].x - path[previous].x);
    const double out = std::atan2(path[next].y - path[i].y, path[next].x - path[i].x);
    if (std::abs(normalizeAngle(out - in)) > cornerAngle) {
      stops.push_back(i);
    }
    previous = i;
  }
  stops.push_back(path.size() - 1);
  return stops;
}

}  // namespace

void validate(const PurePursuitConfig& config) {
  requirePositive(config.lookahead, "pure pursuit lookahead");
  requirePositive(config.maxTranslationalVelocity, "pure pursuit maximum translational velocity");
  requirePositive(config.maxRotationalVelocity, "pure pursuit maximum rotational velocity");
  requirePositive(config.rotationGain, "pure pursuit rotation gain");
  requirePositive(config.goalTolerance, "pure pursuit goal tolerance");
  requirePositive(config.slowdownDistance, "pure pursuit slowdown distance");
  requirePositive(config.minApproachVelocity, "pure pursuit minimum approach velocity");
  if (config.minApproachVelocity > config.maxTranslationalVelocity) {
    throw ConfigError("pure pursuit minimum approach velocity exceeds the maximum velocity");
  }
  requireAngle(config.cornerAngle, "pure pursuit corner angle");
  requireAngle(config.rotateInPlaceBearing, "pure pursuit turn-on-the-spot bearing");
  requireAngle(config.alignedBearing, "pure pursuit aligned bearing");
  if (config.alignedBearing > config.rotateInPlaceBearing) {
    throw ConfigError("pure pursuit aligned bearing exceeds the turn-on-the-spot bearing");
  }
}

PurePursuit::PurePursuit(const PurePursuitConfig& config, std::vector<WorldPoint> path)
    : config_(config), path_(std::move(path)) {
  validate(config_);
  if (path_.empty()) {
    throw InvalidArgumentError("PurePursuit: the path has no waypoints");
  }
  arcLength_.push_back(0.0);
  for (std::size_t i = 1; i < path_.size(); ++i) {
    arcLength_.push_back(arcLength_.back() + distance(path_[i - 1], path_[i]));
  }
  stops_ = findStops(path_, config_.cornerAngle);
}

WorldPoint PurePursuit::pointAt(double s) const {
  const auto it = std::upper_bound(arcLength_.begin(), arcLength_.end(), s);
  if (it == arcLength_.end()) {
    return path_.back();
  }
  const auto i = static_cast<std::size_t>(it - arcLength_.begin());  // i >= 1 since s >= 0
  const double t = (s - arcLength_[i - 1]) / (arcLength_[i] - arcLength_[i - 1]);
  return {path_[i - 1].x + t * (path_[i].x - path_[i - 1].x),
          path_[i - 1].y + t * (path_[i].y - path_[i - 1].y)};
}

// The closest point to `p` on the path between the current progress and `limit`.
void PurePursuit::project(WorldPoint p, double limit) {
  double bestDistance = distance(p, pointAt(progress_));
  double best = progress_;
  for (std::size_t i = 1; i < path_.size() && arcLength_[i - 1] <= limit; ++i) {
    const double length = arcLength_[i] - arcLength_[i - 1];
    if (arcLength_[i] < progress_ || length <= 0.0) {
      continue;
    }
    const WorldPoint a = path_[i - 1], b = path_[i];
    const double t = std::clamp(((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / (length * length), 0.0, 1.0);
    const double s = std::clamp(arcLength_[i - 1] + t * length, progress_, limit);
    const double d = distance(p, pointAt(s));
    if (d < bestDistance) {
      bestDistance = d;
      best = s;
    }
  }
  progress_ = best;
  offPath_ = bestDistance;
}

VelocityCommand PurePursuit::command(const Pose2D& pose) {
  const WorldPoint position{pose.x, pose.y};
  while (nextStop_ + 1 < stops_.size() &&
         distance(position, path_[stops_[nextStop_]]) <= config_.goalTolerance) {
    progress_ = std::max(progress_, arcLength_[stops_[nextStop_]]);
    ++nextStop_;
  }
  const double stop = arcLength_[stops_[nextStop_]];
  project(position, std::min(progress_ + 2.0 * config_.lookahead, stop));
  if (reached_ || (nextStop_ + 1 == stops_.size() && progress_ + config_.lookahead >= stop &&
                   distance(position, path_.back()) <= config_.goalTolerance)) {
    reached_ = true;
    return {};
  }
  const WorldPoint target = pointAt(std::min(progress_ + config_.lookahead, stop));
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const double dx = target.x - pose.x, dy = target.y - pose.y;
  const double left = -s * dx + c * dy;
  const double bearing = std::atan2(left, c * dx + s * dy);
  turning_ = std::abs(bearing) > (turning_ ? config_.alignedBearing : config_.rotateInPlaceBearing);
  if (turning_) {
    return {0.0, std::clamp(config_.rotationGain * bearing, -config_.maxRotationalVelocity,
                            config_.maxRotationalVelocity)};
  }
  const double curvature = 2.0 * left / std::max(dx * dx + dy * dy, 1e-12);
  const double remaining = stop - progress_ + offPath_;
  double v = config_.maxTranslationalVelocity * std::min(1.0, remaining / config_.slowdownDistance);
  v = std::max(v, config_.minApproachVelocity);
  if (std::abs(curvature) * v > config_.maxRotationalVelocity) {
    v = config_.maxRotationalVelocity / std::abs(curvature);
  }
  return {v, curvature * v};
}

}  // namespace rgnav
