// Tests the hallway scenario generator: the eight environments, deterministic scenario sets and
// worlds for a seed, the hallway openings of every gateway class, clutter per level (none, more
// when strong, never on the approach lanes), and the labels of the approach poses (class of the
// scenario, distances decreasing to half a hallway width, poses the robot fits at).
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <set>

#include "core/common/Errors.h"
#include "core/nav/grid/DiskFootprint.h"
#include "core/sim/scenarios/HallwayScenarios.h"

using rgnav::GatewayClass;
using rgnav::HallwayScenario;
using rgnav::ScenarioSpec;

namespace {

bool freeAt(const HallwayScenario& s, double x, double y) {
  const auto c = s.world.cellOf({x, y});
  return c && s.world.at(*c) == rgnav::Cell::Free;
}

ScenarioSpec spec(std::size_t environment, GatewayClass c, std::uint64_t seed = 1) {
  return {rgnav::thesisEnvironments()[environment], c, seed};
}

}  // namespace

class HallwayScenariosTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(HallwayScenariosTest);
  CPPUNIT_TEST(eightEnvironments);
  CPPUNIT_TEST(scenarioSetIsDeterministic);
  CPPUNIT_TEST(worldsAreDeterministic);
  CPPUNIT_TEST(openingsMatchGatewayClass);
  CPPUNIT_TEST(clutterPerLevel);
  CPPUNIT_TEST(approachPosesAreLabelled);
  CPPUNIT_TEST(badConfigIsConfigError);
  CPPUNIT_TEST_SUITE_END();

 public:
  void eightEnvironments() {
    const auto& envs = rgnav::thesisEnvironments();
    std::set<std::string> names;
    for (const auto& e : envs) names.insert(e.name);
    CPPUNIT_ASSERT_EQUAL(std::size_t{8}, names.size());
    CPPUNIT_ASSERT_EQUAL(std::string("2m uncluttered"), envs[0].name);
    CPPUNIT_ASSERT_EQUAL(2.0, envs[0].width);
    CPPUNIT_ASSERT(envs[2].clutter == rgnav::ClutterLevel::Strong);
    CPPUNIT_ASSERT_EQUAL(3.0, envs[7].width);
    CPPUNIT_ASSERT_EQUAL(std::string("X-Crossing"), std::string(rgnav::gatewayClassName(GatewayClass::XCrossing)));
  }

  void scenarioSetIsDeterministic() {
    const auto a = rgnav::scenarioSet(17, 3);
    const auto b = rgnav::scenarioSet(17, 3);
    const auto c = rgnav::scenarioSet(18, 3);
    CPPUNIT_ASSERT_EQUAL(std::size_t{8 * 8 * 3}, a.size());
    std::set<std::uint64_t> seeds;
    for (std::size_t i = 0; i < a.size(); ++i) {
      CPPUNIT_ASSERT_EQUAL(a[i].seed, b[i].seed);
      CPPUNIT_ASSERT(a[i].gatewayClass == b[i].gatewayClass);
      CPPUNIT_ASSERT_EQUAL(a[i].environment.name, b[i].environment.name);
      seeds.insert(a[i].seed);
    }
    CPPUNIT_ASSERT_EQUAL(a.size(), seeds.size());
    CPPUNIT_ASSERT(a[0].seed != c[0].seed);
    CPPUNIT_ASSERT(a[3].gatewayClass == GatewayClass::TJunction);  // classes inner, layouts innermost
    CPPUNIT_ASSERT_EQUAL(std::string("2m slightly cluttered"), a[8 * 3].environment.name);
    CPPUNIT_ASSERT_THROW(rgnav::scenarioSet(1, 0), rgnav::InvalidArgumentError);
  }

  void worldsAreDeterministic() {
    const HallwayScenario a = rgnav::buildScenario(spec(2, GatewayClass::XCrossing, 5));
    const HallwayScenario b = rgnav::buildScenario(spec(2, GatewayClass::XCrossing, 5));
    const HallwayScenario c = rgnav::buildScenario(spec(2, GatewayClass::XCrossing, 6));
    CPPUNIT_ASSERT(a.world.cells() == b.world.cells());
    CPPUNIT_ASSERT(a.world.cells() != c.world.cells());
    CPPUNIT_ASSERT_EQUAL(a.clutter.size(), b.clutter.size());
  }

  // Probes 3 m into each direction from the gateway centre of uncluttered 2 m worlds.
  void openingsMatchGatewayClass() {
    for (const GatewayClass c : rgnav::kGatewayClasses) {
      const HallwayScenario s = rgnav::buildScenario(spec(0, c));
      const rgnav::GatewayOpenings open = rgnav::openingsOf(c);
      CPPUNIT_ASSERT(freeAt(s, 0.0, 0.0));
      CPPUNIT_ASSERT(freeAt(s, -3.0, 0.0));  // the approach hallway
      CPPUNIT_ASSERT_EQUAL(open.left, freeAt(s, 0.0, 3.0));
      CPPUNIT_ASSERT_EQUAL(open.straight, freeAt(s, 3.0, 0.0));
      CPPUNIT_ASSERT_EQUAL(open.right, freeAt(s, 0.0, -3.0));
      CPPUNIT_ASSERT(!freeAt(s, -3.0, 1.1));  // walls beside the approach
      CPPUNIT_ASSERT(freeAt(s, -3.0, 0.95));  // 2 m wide
    }
    CPPUNIT_ASSERT(!rgnav::openingsOf(GatewayClass::DeadEnd).straight);
    CPPUNIT_ASSERT(rgnav::openingsOf(GatewayClass::LTJunction).left);
    CPPUNIT_ASSERT(!rgnav::openingsOf(GatewayClass::LTJunction).right);
  }

  void clutterPerLevel() {
    std::size_t slight = 0, strong = 0;
    for (const GatewayClass c : rgnav::kGatewayClasses) {
      CPPUNIT_ASSERT(rgnav::buildScenario(spec(0, c)).clutter.empty());
      const HallwayScenario a = rgnav::buildScenario(spec(1, c));
      const HallwayScenario b = rgnav::buildScenario(spec(2, c));
      slight += a.clutter.size();
      strong += b.clutter.size();
      for (const HallwayScenario* s : {&a, &b}) {
        for (const rgnav::ClutterObject& o : s->clutter) {
          // Objects stand off the approach lanes: the robot disk (0.25 m) at offsets up to 0.25 m.
          const bool onApproach = o.centre.x + o.halfX > -10.3 && o.centre.x - o.halfX < -0.7;
          CPPUNIT_ASSERT(!onApproach || std::abs(o.centre.y) - o.halfY >= 0.55 - 1e-9);
        }
      }
    }
    CPPUNIT_ASSERT(slight > 8);
    CPPUNIT_ASSERT(strong > 2 * slight);
  }

  void approachPosesAreLabelled() {
    for (std::size_t e = 0; e < rgnav::thesisEnvironments().size(); ++e) {
      for (const GatewayClass c : rgnav::kGatewayClasses) {
        const HallwayScenario s = rgnav::buildScenario(spec(e, c, 40 + e));
        const double h = s.spec.environment.width / 2.0;
        CPPUNIT_ASSERT_EQUAL(std::size_t{4 * 3}, s.approaches.size());
        for (const rgnav::Approach& a : s.approaches) {
          CPPUNIT_ASSERT(a.poses.size() >= 10);
          CPPUNIT_ASSERT_DOUBLES_EQUAL(-a.startDistance, a.poses.front().pose.x, 1e-12);
          CPPUNIT_ASSERT_DOUBLES_EQUAL(-h, a.poses.back().pose.x, 1e-12);
          CPPUNIT_ASSERT(std::abs(a.lateralOffset) <= h / 4.0 + 1e-12);
          for (std::size_t i = 0; i < a.poses.size(); ++i) {
            const rgnav::LabelledPose& p = a.poses[i];
            CPPUNIT_ASSERT(p.gatewayClass == c);
            CPPUNIT_ASSERT_DOUBLES_EQUAL(std::hypot(p.pose.x, p.pose.y), p.distance, 1e-12);
            CPPUNIT_ASSERT(i == 0 || p.distance < a.poses[i - 1].distance);
            CPPUNIT_ASSERT(!rgnav::diskCollides(s.world, {p.pose.x, p.pose.y}, 0.25));
          }
        }
      }
    }
  }

  void badConfigIsConfigError() {
    rgnav::HallwayScenarioConfig config;
    config.lateralOffsetFractions = {0.9};  // lanes would touch the walls of a 2 m hallway
    CPPUNIT_ASSERT_THROW(rgnav::buildScenario(spec(0, GatewayClass::LTurn), config), rgnav::ConfigError);
    config = rgnav::HallwayScenarioConfig{};
    config.startDistances.clear();
    CPPUNIT_ASSERT_THROW(rgnav::buildScenario(spec(0, GatewayClass::LTurn), config), rgnav::ConfigError);
    config = rgnav::HallwayScenarioConfig{};
    config.sampleSpacing = 0.0;
    CPPUNIT_ASSERT_THROW(rgnav::buildScenario(spec(0, GatewayClass::LTurn), config), rgnav::ConfigError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(HallwayScenariosTest);
