// Tests start/stop order: dependencies first, file order among equals, cycles and unknown names.
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "core/supervision/StartOrder.h"

using Names = std::vector<std::string>;

namespace {

rgnav::ModuleSpec module(const std::string& name, Names after = {}) {
  rgnav::ModuleSpec m;
  m.name = name;
  m.after = std::move(after);
  return m;
}

std::string errorOf(const std::vector<rgnav::ModuleSpec>& modules) {
  try {
    rgnav::startOrder(modules);
  } catch (const rgnav::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

class StartOrderTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(StartOrderTest);
  CPPUNIT_TEST(keepsFileOrderWithoutDependencies);
  CPPUNIT_TEST(startsDependenciesFirstAndStaysStable);
  CPPUNIT_TEST(stopOrderIsReverse);
  CPPUNIT_TEST(namesTheCycle);
  CPPUNIT_TEST(rejectsUnknownAndDuplicateNames);
  CPPUNIT_TEST_SUITE_END();

 public:
  void keepsFileOrderWithoutDependencies() {
    CPPUNIT_ASSERT(Names({"C", "A", "B"}) == rgnav::startOrder({module("C"), module("A"), module("B")}));
  }
  void startsDependenciesFirstAndStaysStable() {
    // Kernel waits for Mapper and Gateways, both wait (in)directly for Playback; free Vision goes first.
    const std::vector<rgnav::ModuleSpec> set{module("Kernel", {"Mapper", "Gateways"}), module("Mapper", {"Playback"}),
                                             module("Vision"), module("Playback"), module("Gateways", {"Mapper"})};
    CPPUNIT_ASSERT(Names({"Vision", "Playback", "Mapper", "Gateways", "Kernel"}) == rgnav::startOrder(set));
  }
  void stopOrderIsReverse() {
    const std::vector<rgnav::ModuleSpec> set{module("B", {"A"}), module("A")};
    CPPUNIT_ASSERT(Names({"A", "B"}) == rgnav::startOrder(set));
    CPPUNIT_ASSERT(Names({"B", "A"}) == rgnav::stopOrder(set));
  }
  void namesTheCycle() {
    const std::string selfCycle = errorOf({module("A", {"A"})});
    CPPUNIT_ASSERT_MESSAGE(selfCycle, selfCycle.find("cycle in after: A -> A") != std::string::npos);
    // Free is placed; the cycle among the rest is reported, not the module that merely waits on it.
    const std::string cycle = errorOf({module("Free"), module("Waits", {"C"}), module("B", {"C"}),
                                       module("C", {"D"}), module("D", {"B"})});
    CPPUNIT_ASSERT_MESSAGE(cycle, cycle.find("cycle in after: C -> D -> B -> C") != std::string::npos);
  }
  void rejectsUnknownAndDuplicateNames() {
    const std::string unknown = errorOf({module("A", {"Nobody"})});
    CPPUNIT_ASSERT_MESSAGE(unknown, unknown.find("unknown module 'Nobody'") != std::string::npos);
    const std::string duplicate = errorOf({module("A"), module("A")});
    CPPUNIT_ASSERT_MESSAGE(duplicate, duplicate.find("duplicate module name 'A'") != std::string::npos);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(StartOrderTest);
