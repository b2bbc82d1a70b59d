// Tests the explorer's loop against a scripted strategy: the first goal at once; while driving,
// the strategy asked again only every regoalPeriodS, a different goal replacing the current one
// and an equal one (within two grid cells) keeping it; a failed drive counted with the strategy;
// done once the strategy says so, and for good; a drive the caller lost gets its goal again; a map
// without regions is not explored yet, not done.
#include <cppunit/extensions/HelperMacros.h>

#include <deque>

#include "core/common/Errors.h"
#include "core/nav/exploration/Explorer.h"

using Eigen::Vector2d;
using rgnav::DriveOutcome;
using rgnav::ExplorationGoal;
using rgnav::ExplorerStep;

namespace {

using Action = ExplorerStep::Action;

struct Script {
  std::deque<ExplorationGoal> goals;
  std::vector<ExplorationGoal> failures;
  std::size_t asked = 0;
};

class ScriptedStrategy : public rgnav::ExplorationStrategy {
 public:
  explicit ScriptedStrategy(Script& script) : script_(script) {}
  std::string name() const override { return "scripted"; }
  ExplorationGoal next(const rgnav::ExplorationInput&, const rgnav::PathLength&) override {
    ++script_.asked;
    ExplorationGoal goal = script_.goals.front();
    if (script_.goals.size() > 1) script_.goals.pop_front();
    return goal;
  }
  void failed(const ExplorationGoal& goal) override { script_.failures.push_back(goal); }

 private:
  Script& script_;
};

// The scripted strategy does not look at the map; the explorer only asks it about a map with a region.
rgnav::PlanningMap oneRegion() {
  rgnav::PlanningMap map;
  map.regions.emplace_back();
  map.regions.back().summary.id = rgnav::RegionId{1};
  return map;
}

ExplorationGoal frontierAt(double x, double y) {
  return {ExplorationGoal::Kind::Frontier, Vector2d(x, y), rgnav::RegionId{1}, {}, "frontier"};
}

}  // namespace

class ExplorerTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ExplorerTest);
  CPPUNIT_TEST(keepsReplacesAndFinishes);
  CPPUNIT_TEST(aFailedDriveIsCountedAndAnotherGoalGiven);
  CPPUNIT_TEST(aLostDriveGetsAGoalAgain);
  CPPUNIT_TEST(anEmptyMapIsNotDone);
  CPPUNIT_TEST(aBadConfigurationIsRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void keepsReplacesAndFinishes() {
    Script script;
    script.goals = {frontierAt(1, 1), frontierAt(1.15, 1), frontierAt(5, 5), ExplorationGoal{}};
    rgnav::Explorer explorer(std::make_unique<ScriptedStrategy>(script), {});  // regoal every 3 s, 0.1 m cells

    ExplorerStep step = update(explorer, DriveOutcome::None, 0.0);
    CPPUNIT_ASSERT(step.action == Action::DriveTo && step.goal == frontierAt(1, 1));
    step = update(explorer, DriveOutcome::Driving, 2.9);
    CPPUNIT_ASSERT(step.action == Action::Keep && step.goal == frontierAt(1, 1));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), script.asked);
    step = update(explorer, DriveOutcome::Driving, 3.0);  // 0.15 m off: the same goal
    CPPUNIT_ASSERT(step.action == Action::Keep && step.goal == frontierAt(1, 1));
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), script.asked);
    step = update(explorer, DriveOutcome::Driving, 6.0);  // a different goal
    CPPUNIT_ASSERT(step.action == Action::DriveTo && step.goal == frontierAt(5, 5));
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), explorer.goalsGiven());
    step = update(explorer, DriveOutcome::Reached, 6.5);
    CPPUNIT_ASSERT(step.action == Action::Done);
    CPPUNIT_ASSERT(explorer.done() && !explorer.goal());
    CPPUNIT_ASSERT(update(explorer, DriveOutcome::None, 20.0).action == Action::Done);
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), script.asked);
    CPPUNIT_ASSERT(script.failures.empty());
  }

  void aFailedDriveIsCountedAndAnotherGoalGiven() {
    Script script;
    script.goals = {frontierAt(1, 1), frontierAt(1, 1)};
    rgnav::Explorer explorer(std::make_unique<ScriptedStrategy>(script), {});
    update(explorer, DriveOutcome::None, 0.0);
    // Failed at once, before the regoal period: asked again, and the same goal is a new drive.
    const ExplorerStep step = update(explorer, DriveOutcome::Failed, 0.5);
    CPPUNIT_ASSERT(step.action == Action::DriveTo && step.goal == frontierAt(1, 1));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), script.failures.size());
    CPPUNIT_ASSERT(script.failures[0] == frontierAt(1, 1));
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), explorer.goalsGiven());
  }

  void aLostDriveGetsAGoalAgain() {
    Script script;
    script.goals = {frontierAt(1, 1)};
    rgnav::Explorer explorer(std::make_unique<ScriptedStrategy>(script), {});
    update(explorer, DriveOutcome::None, 0.0);
    // No drive runs to the goal (the caller lost it): the goal is given again at once, not kept.
    const ExplorerStep step = update(explorer, DriveOutcome::None, 0.5);
    CPPUNIT_ASSERT(step.action == Action::DriveTo && step.goal == frontierAt(1, 1));
    CPPUNIT_ASSERT(script.failures.empty());
  }

  void anEmptyMapIsNotDone() {
    rgnav::Explorer explorer(rgnav::makeExplorationStrategy("rg", {}), {});
    const rgnav::PlanningMap empty;
    const ExplorerStep step = explorer.update({empty, {}, {}}, DriveOutcome::None, 0.0, length_);
    CPPUNIT_ASSERT(step.action == Action::Keep);
    CPPUNIT_ASSERT(!explorer.done() && !explorer.goal());
  }

  void aBadConfigurationIsRefused() {
    Script script;
    rgnav::ExplorationConfig bad;
    bad.regoalPeriodS = 0.0;
    CPPUNIT_ASSERT_THROW(rgnav::Explorer(std::make_unique<ScriptedStrategy>(script), bad), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(rgnav::Explorer(nullptr, {}), rgnav::InvalidArgumentError);
  }

 private:
  ExplorerStep update(rgnav::Explorer& explorer, DriveOutcome drive, double now) {
    return explorer.update({map_, {}, {}}, drive, now, length_);
  }

  const rgnav::PlanningMap map_ = oneRegion();
  const rgnav::PathLength length_ = [](const Vector2d&) { return std::optional<double>(1.0); };
};

CPPUNIT_TEST_SUITE_REGISTRATION(ExplorerTest);
