// The PathPlanning module's plan store (PlanStore.h): plans by ID and by request, the bound, and a
// checkpoint that gives back exactly the same plans (every double bit for bit) and numbering.
#include <cppunit/extensions/HelperMacros.h>

#include "core/nav/planning/testing/SamePlan.h"
#include "servers/pathplanning/PlanStore.h"

using namespace rgnav;

namespace {

PlanRecord planNumbered(PlanId id) {
  PlanRecord r;
  r.id = id;
  r.request = 1000 + id;
  r.start = {0.1 * double(id), 1.0 / 3.0, -2.0};
  r.goal = id % 2 ? PlanGoal::inRegionNamed("kitchen") : PlanGoal::at({4.0 / 7.0, 2.0});
  r.plan.targets = {{{1.0 / 7.0, 2.0, 0.3}, RegionId(1)}, {{4.0 / 7.0, 2.0, M_PI / 3}, RegionId(2)}};
  r.plan.route = {{GatewayId(5), 1, RegionId(2), {2.0 / 3.0, 1e-7}}};
  r.plan.path = {{0.1 * double(id), 1.0 / 3.0}, {4.0 / 7.0, 2.0}};
  r.plan.lengthM = std::sqrt(2.0) * double(id);
  r.plan.startRegion = RegionId(1);
  r.plan.goalRegion = RegionId(2);
  r.plan.mapRevision = 9;
  return r;
}

}  // namespace

class PlanStoreTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PlanStoreTest);
  CPPUNIT_TEST(findsPlansByIdAndRequest);
  CPPUNIT_TEST(keepsTheLatest);
  CPPUNIT_TEST(checkpointGivesTheSamePlans);
  CPPUNIT_TEST(damagedCheckpointIsRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void findsPlansByIdAndRequest() {
    PlanStore store;
    CPPUNIT_ASSERT(store.last() == nullptr);
    store.add(planNumbered(1));
    store.add(planNumbered(2));
    CPPUNIT_ASSERT_EQUAL(PlanId(3), store.nextId());
    CPPUNIT_ASSERT_EQUAL(PlanId(2), store.last()->id);
    CPPUNIT_ASSERT_EQUAL(PlanId(1), store.byRequest(1001)->id);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(1002), store.byId(2)->request);
    CPPUNIT_ASSERT(store.byId(3) == nullptr && store.byRequest(7) == nullptr);
    CPPUNIT_ASSERT_THROW(store.add(planNumbered(5)), InvalidArgumentError);
  }

  void keepsTheLatest() {
    PlanStore store(3);
    for (PlanId id = 1; id <= 5; ++id) store.add(planNumbered(id));
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), store.size());
    CPPUNIT_ASSERT(store.byId(2) == nullptr && store.byRequest(1002) == nullptr);
    CPPUNIT_ASSERT(store.byId(3) != nullptr);
  }

  void checkpointGivesTheSamePlans() {
    PlanStore store(3);
    for (PlanId id = 1; id <= 4; ++id) store.add(planNumbered(id));
    const PlanStore back = PlanStore::deserialize(store.serialize(), "plans.state", 3);
    CPPUNIT_ASSERT_EQUAL(PlanId(5), back.nextId());
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), back.size());
    for (PlanId id = 2; id <= 4; ++id)
      CPPUNIT_ASSERT_EQUAL(std::string(), testing::planDifference(*store.byId(id), *back.byId(id)));
    CPPUNIT_ASSERT_EQUAL(store.serialize(), back.serialize());
    const PlanStore empty = PlanStore::deserialize(PlanStore().serialize(), "plans.state");
    CPPUNIT_ASSERT_EQUAL(PlanId(1), empty.nextId());
  }

  void damagedCheckpointIsRefused() {
    PlanStore store;
    store.add(planNumbered(1));
    const std::string text = store.serialize();
    CPPUNIT_ASSERT_THROW(PlanStore::deserialize(text.substr(0, text.size() / 2), "plans.state"), FormatError);
    std::string other = text;
    other.replace(other.find("rgnav-plans"), 11, "rgnav-other");
    try {
      PlanStore::deserialize(other, "plans.state");
      CPPUNIT_FAIL("another format was accepted");
    } catch (const FormatError& e) {
      CPPUNIT_ASSERT(std::string(e.what()).find("plans.state") == 0);
    }
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(PlanStoreTest);
