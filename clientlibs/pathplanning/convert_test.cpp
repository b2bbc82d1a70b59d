// Round trips of the PathPlanning.idl conversions: every kind of goal, a target pose, and a whole
// plan with every field set.
#include <cppunit/extensions/HelperMacros.h>

#include "clientlibs/pathplanning/convert.h"
#include "core/nav/planning/testing/SamePlan.h"

using namespace rgnav;

class PathPlanningConvertTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PathPlanningConvertTest);
  CPPUNIT_TEST(goalsRoundTrip);
  CPPUNIT_TEST(planRoundTrip);
  CPPUNIT_TEST_SUITE_END();

 public:
  void goalsRoundTrip() {
    for (const PlanGoal& g : {PlanGoal::at({3.25, -1.5}), PlanGoal::inRegion(RegionId(7)),
                              PlanGoal::inRegionNamed("kitchen"), PlanGoal::atObject("the closet")}) {
      const PlanGoal back = fromIdl(toIdl(g));
      CPPUNIT_ASSERT(back.kind == g.kind);
      CPPUNIT_ASSERT(back.point == g.point);
      CPPUNIT_ASSERT(back.region == g.region);
      CPPUNIT_ASSERT_EQUAL(g.name, back.name);
    }
    RGNav::PlanGoal unknown = toIdl(PlanGoal::at({0, 0}));
    unknown.kind = static_cast<RGNav::PlanGoalKind>(9);
    CPPUNIT_ASSERT_THROW(fromIdl(unknown), InvalidArgumentError);
  }

  void planRoundTrip() {
    PlanRecord r;
    r.id = 12;
    r.request = 0xfeedbeefcafe0001ULL;
    r.start = {1.0 / 3.0, 2.5, -0.75};
    r.goal = PlanGoal::atObject("cabinet");
    r.plan.targets = {{{1.2, 2.0, 0.1}, RegionId(1)}, {{3.0, 2.1, 1.5}, RegionId(2)}};
    r.plan.route = {{GatewayId(3), 0, RegionId(1), {2.0, 2.0}}, {GatewayId(3), 1, RegionId(2), {2.5, 2.0}}};
    r.plan.path = {{1.0 / 3.0, 2.5}, {2.0, 2.0}, {2.5, 2.0}, {3.0, 2.1}};
    r.plan.lengthM = 3.14159;
    r.plan.startRegion = RegionId(1);
    r.plan.goalRegion = RegionId(2);
    r.plan.mapRevision = 44;
    const PlanRecord back = fromIdl(toIdl(r));
    CPPUNIT_ASSERT_EQUAL(std::string(), testing::planDifference(r, back));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(PathPlanningConvertTest);
