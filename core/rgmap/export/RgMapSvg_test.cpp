// Tests the RG Map's SVG export on the map of the two-room tour: one freespace fill, one group
// and one label per region, one element per gateway with its crossing points and class label,
// balanced tags, escaped names, a scale bar, the same bytes for the same map, overlays drawn on
// top as polylines with their markers.
#include "core/rgmap/export/RgMapSvg.h"

#include <cppunit/extensions/HelperMacros.h>

#include "core/common/AtomicFile.h"
#include "core/logs/LogTestFiles.h"
#include "core/rgmap/export/MapColours.h"
#include "core/rgmap/export/testing/ExportedFloor.h"

using namespace rgnav;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

class RgMapSvgTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RgMapSvgTest);
  CPPUNIT_TEST(oneFillAndLabelPerRegion);
  CPPUNIT_TEST(oneElementPerGateway);
  CPPUNIT_TEST(tagsAreBalanced);
  CPPUNIT_TEST(namesAreEscaped);
  CPPUNIT_TEST(sameMapGivesSameBytes);
  CPPUNIT_TEST(overlaysAreDrawnLast);
  CPPUNIT_TEST_SUITE_END();

 public:
  void setUp() override {
    kernel_ = std::make_unique<RgMappingKernel>(rgnav::testing::twoRoomMap());
    svg_ = exportRgMapSvg(snapshotOf(*kernel_));
  }

  void oneFillAndLabelPerRegion() {
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), count(svg_, "class=\"freespace\""));
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), count(svg_, "class=\"region\""));
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), count(svg_, "class=\"lines\""));
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), count(svg_, "class=\"region-label\""));
    for (const RegionId id : {RegionId{1}, RegionId{2}, RegionId{3}}) {
      CPPUNIT_ASSERT(svg_.find("id=\"region-" + std::to_string(id.value()) + "\"") != std::string::npos);
      CPPUNIT_ASSERT(svg_.find("fill=\"" + hexColour(regionColour(id)) + "\"") != std::string::npos);
    }
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), count(svg_, "class=\"scale-bar\""));
  }

  void oneElementPerGateway() {
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), count(svg_, "class=\"gateway\""));
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), count(svg_, "class=\"gateway-label\""));
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), count(svg_, "class=\"crossing\""));
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), count(svg_, "stroke=\"" + hexColour(kDoorColour) + "\""));
    CPPUNIT_ASSERT(svg_.find(">G1 Narrow-Passage</text>") != std::string::npos);
    CPPUNIT_ASSERT(svg_.find(">G2 Narrow-Passage</text>") != std::string::npos);
    // The RG Graph: the two gateway edges and the hallway's edge between the doors.
    CPPUNIT_ASSERT_EQUAL(kernel_->graph().edges().size(), count(svg_, "<line") - 2 - 1);
  }

  void tagsAreBalanced() {
    CPPUNIT_ASSERT_EQUAL(std::string(), rgnav::testing::unbalancedTags(svg_));
    CPPUNIT_ASSERT(svg_.starts_with("<?xml"));
    CPPUNIT_ASSERT(rgnav::testing::unbalancedTags("<svg><g></svg>") != "");
    CPPUNIT_ASSERT(rgnav::testing::unbalancedTags("<svg/><svg/>") != "");
  }

  void namesAreEscaped() {
    kernel_->nameRegion(RegionId{2}, "R&D <lab>");
    const std::string svg = exportRgMapSvg(snapshotOf(*kernel_));
    CPPUNIT_ASSERT(svg.find(">2 R&amp;D &lt;lab&gt;</text>") != std::string::npos);
    CPPUNIT_ASSERT_EQUAL(std::string(), rgnav::testing::unbalancedTags(svg));
  }

  void sameMapGivesSameBytes() {
    CPPUNIT_ASSERT(svg_ == exportRgMapSvg(snapshotOf(rgnav::testing::twoRoomMap())));
    rgnav::testing::TempDir dir;
    writeRgMapSvg(dir.file("map.svg"), snapshotOf(*kernel_));
    CPPUNIT_ASSERT(svg_ == readCheckpoint(dir.file("map.svg")).value());
  }

  void overlaysAreDrawnLast() {
    const MapPolyline path{{{1.0, 1.0}, {9.0, 1.0}, {9.0, 4.0}}, Rgb{0, 160, 60}, 0.1, 0.09, "plan-path"};
    const std::string svg = exportRgMapSvg(snapshotOf(*kernel_), {path});
    const std::size_t group = svg.find("<g class=\"plan-path\">");
    CPPUNIT_ASSERT(group != std::string::npos);
    CPPUNIT_ASSERT(group > svg.rfind("class=\"region-label\""));
    CPPUNIT_ASSERT(svg.find("points=\"1,-1 9,-1 9,-4\"", group) != std::string::npos);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), count(svg.substr(group), "<circle"));
    CPPUNIT_ASSERT_EQUAL(std::string(), rgnav::testing::unbalancedTags(svg));
  }

 private:
  std::unique_ptr<RgMappingKernel> kernel_;
  std::string svg_;
};

CPPUNIT_TEST_SUITE_REGISTRATION(RgMapSvgTest);
