// NamingDialog: a question per unnamed region the robot is in, asked once; none for a named
// region or outside every region; answers by ID; questions dropped when their region is merged
// away or named elsewhere; a restored dialog does not ask again.
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "core/nav/tasks/NamingDialog.h"

using namespace rgnav;

namespace {

RegionSummaryView region(std::uint64_t id, std::string name = {}) {
  RegionSummaryView r;
  r.id = RegionId(id);
  r.name = std::move(name);
  return r;
}

}  // namespace

class NamingDialogTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(NamingDialogTest);
  CPPUNIT_TEST(asksOncePerUnnamedRegion);
  CPPUNIT_TEST(answerRemovesTheQuestion);
  CPPUNIT_TEST(mergedOrNamedRegionDropsItsQuestion);
  CPPUNIT_TEST(restoredDialogDoesNotAskAgain);
  CPPUNIT_TEST_SUITE_END();

 public:
  void asksOncePerUnnamedRegion() {
    NamingDialog dialog;
    const std::vector<RegionSummaryView> map{region(1), region(2, "kitchen")};
    CPPUNIT_ASSERT(!dialog.observe(RegionId{}, {0, 0}, map));           // in no region
    CPPUNIT_ASSERT(!dialog.observe(RegionId(2), {0, 0}, map));          // named already
    CPPUNIT_ASSERT(!dialog.observe(RegionId(7), {0, 0}, map));          // not in the list
    CPPUNIT_ASSERT(dialog.wouldAsk(RegionId(1), map));
    const auto asked = dialog.observe(RegionId(1), {1.5, -2.0}, map);
    CPPUNIT_ASSERT(asked);
    CPPUNIT_ASSERT_EQUAL(QuestionId{1}, asked->id);
    CPPUNIT_ASSERT_EQUAL(RegionId(1), asked->region);
    CPPUNIT_ASSERT_EQUAL(1.5, asked->where.x());
    CPPUNIT_ASSERT(asked->text.find("name this region?") != std::string::npos);
    CPPUNIT_ASSERT(!dialog.observe(RegionId(1), {2.0, -2.0}, map));     // asked already
    CPPUNIT_ASSERT(!dialog.wouldAsk(RegionId(1), map));
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, dialog.waiting().size());
  }

  void answerRemovesTheQuestion() {
    NamingDialog dialog;
    std::vector<RegionSummaryView> map{region(1), region(2)};
    dialog.observe(RegionId(1), {0, 0}, map);
    dialog.observe(RegionId(2), {0, 0}, map);
    CPPUNIT_ASSERT_EQUAL(RegionId(2), dialog.question(2).region);
    dialog.answered(1);
    CPPUNIT_ASSERT_THROW(dialog.question(1), NotAvailableError);
    CPPUNIT_ASSERT_THROW(dialog.question(5), NotAvailableError);
    map[0].name = "office";
    CPPUNIT_ASSERT(!dialog.observe(RegionId(1), {0, 0}, map));
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, dialog.waiting().size());
    CPPUNIT_ASSERT_EQUAL(QuestionId{2}, dialog.waiting().front().id);
  }

  void mergedOrNamedRegionDropsItsQuestion() {
    NamingDialog dialog;
    dialog.observe(RegionId(1), {0, 0}, {region(1), region(2), region(3)});
    dialog.observe(RegionId(2), {0, 0}, {region(1), region(2), region(3)});
    dialog.observe(RegionId(3), {0, 0}, {region(1), region(2), region(3)});
    // Regions 1 and 2 merged into 4 (unnamed, the robot is elsewhere); 3 was named at the GUI.
    CPPUNIT_ASSERT(!dialog.observe(RegionId{}, {0, 0}, {region(3, "lab"), region(4)}));
    CPPUNIT_ASSERT(dialog.waiting().empty());
    const auto merged = dialog.observe(RegionId(4), {0, 0}, {region(3, "lab"), region(4)});
    CPPUNIT_ASSERT(merged);
    CPPUNIT_ASSERT_EQUAL(QuestionId{4}, merged->id);
  }

  void restoredDialogDoesNotAskAgain() {
    NamingDialog dialog;
    const std::vector<RegionSummaryView> map{region(1), region(2)};
    dialog.observe(RegionId(1), {0, 0}, map);
    NamingDialog restored(dialog.waiting(), dialog.asked(), dialog.nextId());
    CPPUNIT_ASSERT(!restored.observe(RegionId(1), {0, 0}, map));
    CPPUNIT_ASSERT_EQUAL(QuestionId{1}, restored.question(1).id);
    CPPUNIT_ASSERT_EQUAL(QuestionId{2}, restored.observe(RegionId(2), {0, 0}, map)->id);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(NamingDialogTest);
