// Tests the walking people: deterministic walks for a seed (and other walks for another seed),
// people that stay in free space, cross between rooms and keep their speed limits, never start
// near the robot, and stop short of a robot standing in their way (each contact counted once).
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"
#include "core/nav/grid/DiskFootprint.h"
#include "core/sim/people/Crowd.h"
#include "core/sim/scenarios/GridDrawing.h"

using namespace rgnav;

namespace {

constexpr double kDt = 0.05;

// Two 5 x 4 m rooms (x 0..5 and 5.2..10.2, y 0..4) in 0.2 m walls, joined by a 1 m door at y = 2.
OccupancyGrid twoRooms() {
  OccupancyGrid grid(216, 88, 0.05, {-0.2, -0.2}, Cell::Occupied);
  fillRect(grid, {0.0, 0.0, 4.99, 3.99}, Cell::Free);
  fillRect(grid, {5.2, 0.0, 10.19, 3.99}, Cell::Free);
  fillRect(grid, {4.9, 1.5, 5.3, 2.49}, Cell::Free);
  return grid;
}

// A corridor 1 m wide (y 0..1) and 12 m long.
OccupancyGrid corridor() {
  OccupancyGrid grid(248, 28, 0.05, {-0.2, -0.2}, Cell::Occupied);
  fillRect(grid, {0.0, 0.0, 11.99, 0.99}, Cell::Free);
  return grid;
}

PeopleConfig people(int count, std::uint64_t seed) {
  PeopleConfig config;
  config.count = count;
  config.seed = seed;
  return config;
}

const Footprint kRobot = Footprint::disk(0.25);

std::vector<WorldPoint> positionsAfter(const OccupancyGrid& grid, std::uint64_t seed, int steps) {
  const Pose2D robot{1.0, 1.0, 0.0};
  Crowd crowd(grid, people(4, seed), seed, kRobot, robot);
  for (int k = 0; k < steps; ++k) crowd.step(kDt, kRobot, robot);
  std::vector<WorldPoint> out;
  for (const Person& p : crowd.people()) out.push_back(p.position);
  return out;
}

bool same(const std::vector<WorldPoint>& a, const std::vector<WorldPoint>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].x != b[i].x || a[i].y != b[i].y) return false;
  return true;
}

}  // namespace

class CrowdTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CrowdTest);
  CPPUNIT_TEST(walksAreDeterministicForASeed);
  CPPUNIT_TEST(peopleStayInFreeSpaceAndKeepTheirSpeed);
  CPPUNIT_TEST(peopleNeverStartNearTheRobot);
  CPPUNIT_TEST(peopleStopShortOfAStandingRobot);
  CPPUNIT_TEST(badConfigurationsAreConfigErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void walksAreDeterministicForASeed() {
    const OccupancyGrid grid = twoRooms();
    const auto a = positionsAfter(grid, 5, 300);
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), a.size());
    CPPUNIT_ASSERT(same(a, positionsAfter(grid, 5, 300)));
    CPPUNIT_ASSERT(!same(a, positionsAfter(grid, 6, 300)));
  }

  void peopleStayInFreeSpaceAndKeepTheirSpeed() {
    const OccupancyGrid grid = twoRooms();
    const Pose2D robot{9.0, 3.0, 0.0};
    Crowd crowd(grid, people(5, 11), 11, kRobot, robot);
    std::vector<double> walked(5, 0.0);
    std::vector<bool> left(5, false), right(5, false);
    for (int k = 0; k < 2400; ++k) {  // two minutes
      crowd.step(kDt, kRobot, robot);
      for (std::size_t i = 0; i < 5; ++i) {
        const Person& p = crowd.people()[i];
        CPPUNIT_ASSERT(!diskCollides(grid, p.position, p.radius));
        CPPUNIT_ASSERT_DOUBLES_EQUAL(p.position.x, crowd.obstacles()[i].centre.x, 0.0);
        const double speed = std::hypot(p.velocity.x, p.velocity.y);
        CPPUNIT_ASSERT(speed <= 1.2 + 1e-9);
        walked[i] += speed * kDt;
        (p.position.x < 5.0 ? left : right)[i] = true;
      }
    }
    int crossed = 0;
    for (std::size_t i = 0; i < 5; ++i) {
      CPPUNIT_ASSERT(walked[i] > 0.5 * 120 * 0.5);  // at least half the time at the slowest speed
      crossed += left[i] && right[i];
    }
    CPPUNIT_ASSERT(crossed >= 3);
  }

  void peopleNeverStartNearTheRobot() {
    const OccupancyGrid grid = twoRooms();
    const Pose2D robot{2.5, 2.0, 0.0};
    const Footprint jackal = Footprint::rectangle(0.508, 0.430);
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const Crowd crowd(grid, people(30, seed), seed, jackal, robot);
      for (const Person& p : crowd.people())
        CPPUNIT_ASSERT(!jackal.overlapsDisk(robot, p.position, p.radius + Crowd::kStartClearance));
    }
  }

  void peopleStopShortOfAStandingRobot() {
    const OccupancyGrid grid = corridor();
    const Pose2D robot{6.0, 0.5, 0.0};  // blocks the corridor: nobody fits past
    Crowd crowd(grid, people(3, 2), 2, kRobot, robot);
    int contacts = 0;
    for (int k = 0; k < 2400; ++k) {
      contacts += static_cast<int>(crowd.step(kDt, kRobot, robot).size());
      for (const Person& p : crowd.people()) {
        CPPUNIT_ASSERT(!kRobot.overlapsDisk(robot, p.position, p.radius));
        CPPUNIT_ASSERT(!diskCollides(grid, p.position, p.radius));
      }
    }
    // People on either side keep walking into the robot, one contact each time, not per step.
    CPPUNIT_ASSERT(contacts >= 3);
    CPPUNIT_ASSERT(contacts < 2400 / 20);
  }

  void badConfigurationsAreConfigErrors() {
    PeopleConfig bad;
    bad.count = -1;
    CPPUNIT_ASSERT_THROW(validate(bad), ConfigError);
    bad = PeopleConfig{};
    bad.radius = 0.0;
    CPPUNIT_ASSERT_THROW(validate(bad), ConfigError);
    bad = PeopleConfig{};
    bad.minSpeed = 1.5;
    CPPUNIT_ASSERT_THROW(validate(bad), ConfigError);
    bad = PeopleConfig{};
    bad.maxSpeed = NAN;
    CPPUNIT_ASSERT_THROW(validate(bad), ConfigError);
    // No room for a person: a corridor too narrow for its radius.
    OccupancyGrid narrow(100, 20, 0.05, {0.0, 0.0}, Cell::Occupied);
    fillRect(narrow, {0.2, 0.4, 4.8, 0.7}, Cell::Free);
    CPPUNIT_ASSERT_THROW(Crowd(narrow, people(1, 1), 1, kRobot, {1.0, 0.55, 0.0}), InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(CrowdTest);
