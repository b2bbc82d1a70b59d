// TourDriver: follows a planned room tour step by step with the pure-pursuit waypoint follower
// on the true pose (the stand-in for a person with a joystick): one leg per room, from where the
// robot stands along the route to the room's visiting point. A visit is given up, and the tour
// goes on to the next room, when the robot stayed within kStuckRadius of one place for
// stuckSeconds (distance to the goal is no measure of progress on a winding route).
#pragma once

#include <optional>
#include <set>
#include <vector>

#include "core/common/SensorData.h"
#include "core/nav/grid/PurePursuit.h"
#include "core/nav/grid/TourPlanner.h"

namespace rgnav {

class TourDriver {
 public:
  static constexpr double kStuckRadius = 0.2;  // m

  TourDriver(Tour tour, const PurePursuitConfig& follower, double stuckSeconds = 60.0);

  // The command for the robot at its true pose at simulated time `now`; zero when finished.
  VelocityCommand command(const Pose2D& truePose, Timestamp now);
  bool finished() const { return next_ >= tour_.visits.size(); }

  const std::set<int>& roomsVisited() const { return visited_; }
  const std::vector<int>& roomsMissed() const { return missed_; }
  const Tour& tour() const { return tour_; }

 private:
  void startLeg(const Pose2D& from, Timestamp now);
  void endLeg(bool reached, const Pose2D& at, Timestamp now);

  Tour tour_;
  PurePursuitConfig follower_;
  double stuckSeconds_;
  std::size_t next_ = 0;        // index of the visit being driven to
  std::size_t routeAt_ = 0;     // route index the current leg starts after
  std::optional<PurePursuit> pursuit_;
  Pose2D anchor_;               // where the robot was when it last moved kStuckRadius
  Timestamp anchorTime_ = 0.0;
  std::set<int> visited_;
  std::vector<int> missed_;
};

}  // namespace rgnav
