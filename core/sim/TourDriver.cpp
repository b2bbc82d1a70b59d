// Step-by-step tour following (see TourDriver.h).
#include "core/sim/TourDriver.h"

#include <cmath>

namespace rgnav {

namespace {
double distanceBetween(const Pose2D& a, const Pose2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }
}  // namespace

TourDriver::TourDriver(Tour tour, const PurePursuitConfig& follower, double stuckSeconds)
    : tour_(std::move(tour)), follower_(follower), stuckSeconds_(stuckSeconds) {}

void TourDriver::startLeg(const Pose2D& from, Timestamp now) {
  const RoomVisit& visit = tour_.visits[next_];
  std::vector<WorldPoint> leg{{from.x, from.y}};
  for (std::size_t i = routeAt_ + 1; i <= visit.routeIndex && i < tour_.route.size(); ++i) leg.push_back(tour_.route[i]);
  pursuit_.emplace(follower_, std::move(leg));
  anchor_ = from;
  anchorTime_ = now;
}

void TourDriver::endLeg(bool reached, const Pose2D& at, Timestamp now) {
  const RoomVisit& visit = tour_.visits[next_];
  if (reached)
    visited_.insert(visit.room);
  else
    missed_.push_back(visit.room);
  routeAt_ = visit.routeIndex;
  pursuit_.reset();
  ++next_;
  if (!finished()) startLeg(at, now);
}

VelocityCommand TourDriver::command(const Pose2D& truePose, Timestamp now) {
  if (finished()) return {};
  if (!pursuit_) startLeg(truePose, now);
  if (distanceBetween(truePose, anchor_) > kStuckRadius) {
    anchor_ = truePose;
    anchorTime_ = now;
  }
  VelocityCommand cmd = pursuit_->command(truePose);
  if (pursuit_->reached()) {
    endLeg(true, truePose, now);
    return finished() ? VelocityCommand{} : pursuit_->command(truePose);
  }
  if (now - anchorTime_ > stuckSeconds_) {
    endLeg(false, truePose, now);
    return finished() ? VelocityCommand{} : pursuit_->command(truePose);
  }
  return cmd;
}

}  // namespace rgnav
