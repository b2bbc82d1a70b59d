// Tests the explorer's loop against a scripted strategy: the first goal at once; while driving,
// the strategy asked again only every regoalPeriodS, a different goal replacing the current one
// and an equal one (within two grid cells) keeping it; a failed drive counted with the strategy;
// done once the strategy says so, and for good.
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

ExplorationGoal frontierAt(double x, double y) {
  return {ExplorationGoal::Kind::Frontier, Vector2d(x, y), rgnav::RegionId{1}, {}, "frontier"};
}

}  // namespace

class ExplorerTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ExplorerTest);
  CPPUNIT_TEST(keepsReplacesAndFinishes);
  CPPUNIT_TEST(aFailedDriveIsCountedAndAnotherGoalGiven);
  CPPUNIT_TEST(aBadConfigurationIsRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void keepsReplacesAndFinishes() {
    Script script;
    script.goals = {frontierAt(1, 1), frontierAt(1.15, 1), frontierAt(5, 5), ExplorationGoal{}};
    rgnav::Explorer explorer(std::make_unique<ScriptedStrategy>(script), {});  // regoal every 3 s, 0.1 m cells
    const rgnav::PlanningMap map;
    const rgnav::ExplorationInput input{map, {}, {}};
    const auto length = [](const Vector2d&) { return std::optional<double>(1.0); };

    ExplorerStep step = explorer.update(input, DriveOutcome::None, 0.0, length);
    CPPUNIT_ASSERT(step.action == Action::DriveTo && step.goal == frontierAt(1, 1));
    step = explorer.update(input, DriveOutcome::Driving, 2.9, length);
    CPPUNIT_ASSERT(step.action == Action::Keep && step.goal == frontierAt(1, 1));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), script.asked);
    step = explorer.update(input, DriveOutcome::Driving, 3.0, length);  // 0.15 m off: the same goal
    CPPUNIT_ASSERT(step.action == Action::Keep && step.goal == frontierAt(1, 1));
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), script.asked);
    step = explorer.update(input, DriveOutcome::Driving, 6.0, length);  // a different goal
    CPPUNIT_ASSERT(step.action == Action::DriveTo && step.goal == frontierAt(5, 5));
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), explorer.goalsGiven());
    step = explorer.update(input, DriveOutcome::Reached, 6.5, length);
    CPPUNIT_ASSERT(step.action == Action::Done);
    CPPUNIT_ASSERT(explorer.done() && !explorer.goal());
    CPPUNIT_ASSERT(explorer.update(input, DriveOutcome::None, 20.0, length).action == Action::Done);
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), script.asked);
    CPPUNIT_ASSERT(script.failures.empty());
  }

  void aFailedDriveIsCountedAndAnotherGoalGiven() {
    Script script;
    script.goals = {frontierAt(1, 1), frontierAt(1, 1)};
    rgnav::Explorer explorer(std::make_unique<ScriptedStrategy>(script), {});
    const rgnav::PlanningMap map;
    const rgnav::ExplorationInput input{map, {}, {}};
    const auto length = [](const Vector2d&) { return std::optional<double>(1.0); };
    explorer.update(input, DriveOutcome::None, 0.0, length);
    // Failed at once, before the regoal period: asked again, and the same goal is a new drive.
    const ExplorerStep step = explorer.update(input, DriveOutcome::Failed, 0.5, length);
    CPPUNIT_ASSERT(step.action == Action::DriveTo && step.goal == frontierAt(1, 1));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), script.failures.size());
    CPPUNIT_ASSERT(script.failures[0] == frontierAt(1, 1));
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), explorer.goalsGiven());
  }

  void aBadConfigurationIsRefused() {
    Script script;
    rgnav::ExplorationConfig bad;
    bad.regoalPeriodS = 0.0;
    CPPUNIT_ASSERT_THROW(rgnav::Explorer(std::make_unique<ScriptedStrategy>(script), bad), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(rgnav::Explorer(nullptr, {}), rgnav::InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ExplorerTest);
