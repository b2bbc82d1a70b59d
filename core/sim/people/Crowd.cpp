// Crowd: placing people, picking goals in their free-space component, walking the planned
// paths, and stopping short of the robot (see Crowd.h).
#include "core/sim/people/Crowd.h"

#include <cmath>
#include <string>

#include "core/common/Errors.h"
#include "core/common/ValueChecks.h"
#include "core/nav/grid/PlanningErrors.h"

namespace rgnav {

namespace {

constexpr int kPlacementAttempts = 10000;
constexpr int kGoalAttempts = 200;
constexpr int kAwayAttempts = 5;           // goals tried for one leading away after a contact
constexpr double kComfortMargin = 0.5;     // m beyond the radius where paths prefer to run

GridPlannerConfig plannerConfig(const PeopleConfig& config) {
  validate(config);
  GridPlannerConfig planner;
  planner.robotRadius = config.radius;
  planner.comfortClearance = config.radius + kComfortMargin;
  return planner;
}

double distance(WorldPoint a, WorldPoint b) { return std::hypot(b.x - a.x, b.y - a.y); }

}  // namespace

void validate(const PeopleConfig& config) {
  if (config.count < 0) throw ConfigError("people: count must not be negative");
  requirePositive(config.radius, "people: radius_m");
  requirePositive(config.minSpeed, "people: min_speed_mps");
  requirePositive(config.maxSpeed, "people: max_speed_mps");
  if (config.minSpeed > config.maxSpeed) throw ConfigError("people: min_speed_mps must not exceed max_speed_mps");
}

Crowd::Crowd(const OccupancyGrid& grid, const PeopleConfig& config, std::uint64_t seed, const Footprint& robot,
             const Pose2D& robotPose)
    : config_(config),
      planner_(grid, plannerConfig(config)),
      rng_(seed),
      components_(static_cast<std::size_t>(grid.width()) * static_cast<std::size_t>(grid.height()), -1) {
  for (int row = 0; row < grid.height(); ++row)
    for (int col = 0; col < grid.width(); ++col)
      if (planner_.traversable({col, row})) freeCells_.push_back({col, row});
  for (int i = 0; i < config_.count; ++i) {
    std::optional<WorldPoint> start;
    for (int attempt = 0; attempt < kPlacementAttempts && !start && !freeCells_.empty(); ++attempt) {
      const WorldPoint p = grid.center(randomFreeCell());
      if (!robot.overlapsDisk(robotPose, p, config_.radius + kStartClearance)) start = p;
    }
    if (!start)
      throw InvalidArgumentError("simulation: no room for person " + std::to_string(i + 1) + " of " +
                                 std::to_string(config_.count) + " away from the robot");
    Walk walk;
    walk.anchor = *start;
    walk.component = componentOf(*grid.cellOf(*start));
    newLeg(walk, std::nullopt);
    walks_.push_back(std::move(walk));
    people_.push_back({*start, {0.0, 0.0}, config_.radius});
    obstacles_.push_back({*start, config_.radius});
  }
}

const CellIndex& Crowd::randomFreeCell() {
  std::uniform_int_distribution<std::size_t> pick(0, freeCells_.size() - 1);
  return freeCells_[pick(rng_)];
}

int Crowd::componentOf(CellIndex cell) {
  const OccupancyGrid& grid = planner_.grid();
  const auto index = [&](CellIndex c) { return static_cast<std::size_t>(c.row) * grid.width() + c.col; };
  if (components_[index(cell)] < 0) {
    const std::vector<bool> reachable = planner_.reachableFrom(grid.center(cell));
    for (std::size_t k = 0; k < reachable.size(); ++k)
      if (reachable[k]) components_[k] = componentCount_;
    ++componentCount_;
  }
  return components_[index(cell)];
}

void Crowd::newLeg(Walk& walk, const std::optional<WorldPoint>& awayFrom) {
  const OccupancyGrid& grid = planner_.grid();
  walk.path.clear();
  walk.speed = std::uniform_real_distribution<double>(config_.minSpeed, config_.maxSpeed)(rng_);
  int awayTries = 0;
  for (int attempt = 0; attempt < kGoalAttempts; ++attempt) {
    const CellIndex cell = randomFreeCell();
    const WorldPoint goal = grid.center(cell);
    if (components_[static_cast<std::size_t>(cell.row) * grid.width() + cell.col] != walk.component) continue;
    if (distance(goal, walk.anchor) < grid.resolution()) continue;
    std::vector<WorldPoint> path;
    try {
      path = planner_.plan(walk.anchor, goal);
    } catch (const NoPathError&) {
      continue;
    }
    // After a contact: the first leg must not head back to the robot, for a few tries.
    if (awayFrom && awayTries++ < kAwayAttempts) {
      const WorldPoint next = path.size() > 1 ? path[1] : goal;
      const double dot = (next.x - walk.anchor.x) * (walk.anchor.x - awayFrom->x) +
                         (next.y - walk.anchor.y) * (walk.anchor.y - awayFrom->y);
      if (dot < 0.0) continue;
    }
    walk.path = std::move(path);
    return;
  }
}

std::vector<WorldPoint> Crowd::step(double dt, const Footprint& robot, const Pose2D& robotPose) {
  std::vector<WorldPoint> contacts;
  for (std::size_t i = 0; i < people_.size(); ++i) {
    Person& person = people_[i];
    Walk& walk = walks_[i];
    if (walk.path.empty()) newLeg(walk, std::nullopt);
    // Where the person would be after dt along its path, and the last waypoint it would pass.
    WorldPoint p = person.position;
    WorldPoint anchor = walk.anchor;
    std::size_t passed = 0;
    double remaining = walk.speed * dt;
    while (remaining > 0.0 && passed < walk.path.size()) {
      const WorldPoint target = walk.path[passed];
      const double d = distance(p, target);
      if (d <= remaining) {
        remaining -= d;
        p = target;
        anchor = target;
        ++passed;
      } else {
        p = {p.x + (target.x - p.x) * remaining / d, p.y + (target.y - p.y) * remaining / d};
        remaining = 0.0;
      }
    }
    if (robot.overlapsDisk(robotPose, p, person.radius)) {
      if (!walk.inContact) contacts.push_back(person.position);
      walk.inContact = true;
      person.velocity = {0.0, 0.0};
      // The new path starts at the last waypoint: back the way it came (free of walls), then on
      // somewhere else.
      newLeg(walk, WorldPoint{robotPose.x, robotPose.y});
      continue;
    }
    walk.inContact = false;
    walk.path.erase(walk.path.begin(), walk.path.begin() + static_cast<std::ptrdiff_t>(passed));
    walk.anchor = anchor;
    person.velocity = {(p.x - person.position.x) / dt, (p.y - person.position.y) / dt};
    person.position = p;
    obstacles_[i].centre = p;
  }
  return contacts;
}

}  // namespace rgnav
