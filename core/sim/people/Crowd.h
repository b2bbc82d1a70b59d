// Crowd: people walking through a simulated world, the moving obstacles of issue "Motion" (the
// thesis's collision avoidance, 5.5, must react to them; the thesis itself has no people model,
// only clutter by people in real scans, 4.1.2). Each person is a cylinder (a disk seen from
// above) that walks at its own speed, drawn from [minSpeed, maxSpeed] for every leg, between
// random points of the free space it can reach, along a path around the walls planned on the
// world grid (GridPlanner with the person's radius; its line-of-sight shortcuts make the legs
// straight where there is room). Seeded with its own random number generator: the same world,
// configuration, seed and robot motion give the same walks, bit for bit.
// Deliberate simplifications: people walk through each other (only walls and the robot stop
// them) and do not see the robot coming; a person whose next step would overlap the robot stops
// short of it (it never pushes through the robot) and turns to a new goal. People never start
// within kStartClearance of the robot.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <span>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/nav/grid/Footprint.h"
#include "core/nav/grid/GridPlanner.h"
#include "core/raster/OccupancyGrid.h"
#include "core/sim/people/Person.h"
#include "core/sim/world/DiskObstacle.h"

namespace rgnav {

struct PeopleConfig {
  int count = 0;
  double radius = 0.25;                  // m
  double minSpeed = 0.5;                 // m/s
  double maxSpeed = 1.2;                 // m/s
  std::optional<std::uint64_t> seed;     // own seed; else one derived from the simulation's
};

// Throws ConfigError for a negative count, a non-positive radius or speed, or minSpeed > maxSpeed.
void validate(const PeopleConfig& config);

class Crowd {
 public:
  static constexpr double kStartClearance = 1.0;  // m between a person and the robot at the start

  // Places `config.count` people at random free points (none within kStartClearance of the robot
  // at `robotPose`). Keeps a reference to `grid`, which must outlive the crowd. Throws ConfigError
  // for a bad configuration and InvalidArgumentError if the world has no room for a person.
  Crowd(const OccupancyGrid& grid, const PeopleConfig& config, std::uint64_t seed, const Footprint& robot,
        const Pose2D& robotPose);

  // Walks everybody `dt` seconds on. A person whose step would overlap the robot (footprint
  // `robot` at `robotPose`) stays where it was and takes a new goal; returns where the people are
  // who came into contact with the robot in this step and were not in contact the step before.
  std::vector<WorldPoint> step(double dt, const Footprint& robot, const Pose2D& robotPose);

  const std::vector<Person>& people() const { return people_; }
  // The people as obstacles for the robot's collision check and the laser.
  const std::vector<DiskObstacle>& obstacles() const { return obstacles_; }

 private:
  struct Walk {
    WorldPoint anchor;              // the last waypoint reached: a cell centre the planner starts from
    std::vector<WorldPoint> path;   // waypoints still ahead, the next first
    double speed = 0.0;
    int component = -1;             // the free-space component the person walks in
    bool inContact = false;
  };

  const CellIndex& randomFreeCell();
  int componentOf(CellIndex cell);
  // A new goal and path from the walk's anchor; after a contact (`awayFrom` set) the first goals
  // tried must lead away from that point.
  void newLeg(Walk& walk, const std::optional<WorldPoint>& awayFrom);

  PeopleConfig config_;
  GridPlanner planner_;
  std::mt19937_64 rng_;
  std::vector<CellIndex> freeCells_;  // every cell a person fits in
  std::vector<int> components_;       // per cell: component label, -1 not yet labelled
  int componentCount_ = 0;
  std::vector<Person> people_;
  std::vector<Walk> walks_;
  std::vector<DiskObstacle> obstacles_;
};

}  // namespace rgnav
